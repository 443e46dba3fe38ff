set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.783766 9.877
0.424742 10.56
0.198122 11.053
0.001 13.95
EOD
$t0 << EOD
0.611273 15.8415 256
0.250744 18.592 512
0.152189 21.797 1024
0.067575 28.4155 2048
0.0271075 54.0425 4096
EOD
$t1 << EOD
0.0193625 30.056 256
0.00116175 23.1485 512
0.00387249 30.338 1024
0.001 43.3885 2048
0.001 82.6085 4096
EOD
$t2 << EOD
0.00290437 42.117 256
0.001 51.733 512
0.001 47.8565 1024
0.001 62.2475 2048
0.001 75.3435 4096
EOD
$t3 << EOD
0.001 13.95 ""
EOD
$t4 << EOD
0.783766 9.877 256
0.424742 10.56 512
0.235343 15.842 1024
0.132211 20.3355 2048
0.0783184 35.7055 4096
EOD
$t5 << EOD
0.182808 217.189 512
0.190174 205.925 2048
EOD
$t6 << EOD
0.402448 11.5935 256
0.198122 11.053 512
0.101387 15.9995 1024
0.0517599 23.53 2048
0.0232629 54.4155 4096
EOD
$t7 << EOD
0.454208 13.574 256
0.20956 12.285 512
0.111662 19.8735 1024
0.0548617 31.682 2048
0.0275278 76.7345 4096
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
