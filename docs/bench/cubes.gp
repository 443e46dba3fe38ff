set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
6.70935 34.46
4.06977 36.6345
2.04638 39.8325
1.47184 41.1115
0.729185 44.1005
0.384264 47.122
0.0204797 50.277
0.00197611 62.255
0.00179646 63.1575
EOD
$t0 << EOD
2.62194 41.003 256
1.47184 41.1115 512
0.729185 44.1005 1024
0.384264 47.122 2048
0.189347 55.105 4096
EOD
$t1 << EOD
0.474985 52.938 256
0.145693 54.364 512
0.0443727 56.6575 1024
0.0204797 50.277 2048
0.0104195 73.8465 4096
EOD
$t2 << EOD
0.00197611 71.304 256
0.00197611 62.255 512
0.00179646 63.1575 1024
0.00197611 81.578 2048
0.00197611 90.2845 4096
EOD
$t3 << EOD
0.00862303 102.413 ""
EOD
$t4 << EOD
6.70935 34.46 256
4.06977 36.6345 512
2.21902 47.541 1024
1.14077 63.557 2048
0.591225 106.612 4096
EOD
$t5 << EOD
2.44718 348.852 512
2.08141 418.859 2048
EOD
$t6 << EOD
2.50053 48.4745 256
1.51121 50.6535 512
0.723626 52.899 1024
0.403671 74.1305 2048
0.196716 137.611 4096
EOD
$t7 << EOD
3.05421 45.636 256
2.04638 39.8325 512
1.10035 52.6995 1024
0.524395 72.4195 2048
0.276839 145.394 4096
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
