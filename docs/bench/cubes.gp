set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.62194 31.208
1.47184 32.616
0.729185 33.892
0.384264 41.74
0.145693 45.219
0.0443727 47.742
0.0204797 49.3495
0.00197611 64.976
0.00179646 72.2175
EOD
$t0 << EOD
2.62194 31.208 256
1.47184 32.616 512
0.729185 33.892 1024
0.384264 41.74 2048
0.189347 48.012 4096
EOD
$t1 << EOD
0.474985 44.8385 256
0.145693 45.219 512
0.0443727 47.742 1024
0.0204797 49.3495 2048
0.0104195 78.9155 4096
EOD
$t2 << EOD
0.00197611 64.976 256
0.00197611 72.5495 512
0.00179646 72.2175 1024
0.00197611 74.2215 2048
0.00197611 96.48 4096
EOD
$t3 << EOD
0.00862303 119.07 ""
EOD
$t4 << EOD
6.70935 42.3105 256
4.06977 53.896 512
2.21902 52.512 1024
1.14077 62.657 2048
0.591225 88.705 4096
EOD
$t5 << EOD
2.44718 416.552 512
2.08141 446.526 2048
EOD
$t6 << EOD
2.50053 54.0995 256
1.51121 56.308 512
0.723626 62.265 1024
0.403671 89.386 2048
0.196716 138.22 4096
EOD
$t7 << EOD
3.05421 46.813 256
2.04638 47.814 512
1.10035 50.7955 1024
0.524395 76.821 2048
0.276839 149.27 4096
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
