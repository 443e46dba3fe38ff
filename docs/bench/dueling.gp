set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.454208 8.596
0.20956 9.243
0.001 13.2795
EOD
$t0 << EOD
0.611273 15.917 256
0.250744 14.463 512
0.152189 15.9225 1024
0.067575 13.8565 2048
0.0271075 17.644 4096
EOD
$t1 << EOD
0.0193625 21.195 256
0.00116175 22.062 512
0.00387249 21.697 1024
0.001 26.382 2048
0.001 36.1165 4096
EOD
$t2 << EOD
0.00329162 40.1745 256
0.001 41.3625 512
0.00116175 38.1835 1024
0.001 31.827 2048
0.001 39.4295 4096
EOD
$t3 << EOD
0.001 13.2795 ""
EOD
$t4 << EOD
0.783766 12.814 256
0.424742 9.545 512
0.235343 12.6875 1024
0.132211 19.057 2048
0.0783184 32.8815 4096
EOD
$t5 << EOD
0.182808 180.432 512
0.190174 237.294 2048
EOD
$t6 << EOD
0.402448 12.8285 256
0.198122 15.1315 512
0.101387 22.0305 1024
0.0517599 28.334 2048
0.0232629 50.7645 4096
EOD
$t7 << EOD
0.454208 8.596 256
0.20956 9.243 512
0.111662 15.5425 1024
0.0548617 24.0475 2048
0.0275278 63.8275 4096
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
