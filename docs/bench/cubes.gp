set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.729185 36.755
0.474985 46.061
0.384264 53.961
0.145693 56.96
0.0443727 61.1335
0.0204797 75.2355
0.0104195 82.427
0.0077248 87.82
EOD
$t0 << EOD
2.62194 44.991 256
1.47184 43.8905 512
0.729185 36.755 1024
0.384264 53.961 2048
0.189347 64.2085 4096
EOD
$t1 << EOD
0.474985 46.061 256
0.145693 56.96 512
0.0443727 61.1335 1024
0.0204797 75.2355 2048
0.0104195 82.427 4096
EOD
$t2 << EOD
0.00790444 90.337 256
0.0077248 87.82 512
0.00790444 89.896 1024
0.00790444 96.6825 2048
0.0077248 118.053 4096
EOD
$t3 << EOD
0.00862303 124.094 ""
EOD
$t4 << EOD
6.70935 42.726 256
4.06977 42.779 512
2.21902 53.6535 1024
1.14077 52.775 2048
0.591225 84.3945 4096
EOD
$t5 << EOD
2.44718 384.077 512
2.08141 430.901 2048
EOD
$t6 << EOD
2.50053 44.9915 256
1.51121 51.514 512
0.723626 58.847 1024
0.403671 84.462 2048
0.196716 145.067 4096
EOD
$t7 << EOD
3.05421 44.9355 256
2.04638 41.3775 512
1.10035 56.846 1024
0.524395 79.122 2048
0.276839 145.197 4096
EOD
plot $front using 1:2 with steps lw 6 lc rgb '#c8c8c8' title 'Pareto front', \
     $t0 using 1:2 with linespoints pt 7 ps 1.3 lw 2 title 'shadowmap', \
     $t0 using 1:2:3 with labels offset 0.8,0.6 font ',8' notitle, \
     $t1 using 1:2 with linespoints pt 7 ps 1.3 lw 2 title 'silhouette', \
     $t1 using 1:2:3 with labels offset 0.8,0.6 font ',8' notitle, \
     $t2 using 1:2 with linespoints pt 7 ps 1.3 lw 2 title 'hybrid', \
     $t2 using 1:2:3 with labels offset 0.8,0.6 font ',8' notitle, \
     $t3 using 1:2 with linespoints pt 7 ps 1.3 lw 2 title 'volume', \
     $t3 using 1:2:3 with labels offset 0.8,0.6 font ',8' notitle, \
     $t4 using 1:2 with linespoints pt 6 ps 1.3 lw 2 title 'ShadowMap', \
     $t4 using 1:2:3 with labels offset 0.8,0.6 font ',8' notitle, \
     $t5 using 1:2 with linespoints pt 6 ps 1.3 lw 2 title 'SoftShadowMap', \
     $t5 using 1:2:3 with labels offset 0.8,0.6 font ',8' notitle, \
     $t6 using 1:2 with linespoints pt 6 ps 1.3 lw 2 title 'LightSpacePerspectiveShadowMapCB', \
     $t6 using 1:2:3 with labels offset 0.8,0.6 font ',8' notitle, \
     $t7 using 1:2 with linespoints pt 6 ps 1.3 lw 2 title 'ViewDependentShadowMap', \
     $t7 using 1:2:3 with labels offset 0.8,0.6 font ',8' notitle
