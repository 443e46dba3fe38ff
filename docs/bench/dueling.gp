set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.424742 15.7365
0.00387249 23.6265
0.001 25.1295
EOD
$t0 << EOD
0.611273 22.053 256
0.250744 26.4975 512
0.152189 43.0905 1024
0.067575 52.81 2048
0.0271075 83.3345 4096
EOD
$t1 << EOD
0.0193625 58.66 256
0.00116175 56.936 512
0.00387249 23.6265 1024
0.001 33.411 2048
0.001 75.2155 4096
EOD
$t2 << EOD
0.00290437 34.715 256
0.001 34.9895 512
0.001 38.3575 1024
0.001 54.773 2048
0.001 120.036 4096
EOD
$t3 << EOD
0.001 25.1295 ""
EOD
$t4 << EOD
0.783766 17.5925 256
0.424742 15.7365 512
0.235343 29.9375 1024
0.132211 25.0235 2048
0.0783184 71.7185 4096
EOD
$t5 << EOD
0.182808 371.78 512
0.190174 493.169 2048
EOD
$t6 << EOD
0.402448 26.226 256
0.198122 43.8725 512
0.101387 71.904 1024
0.0517599 93.5895 2048
0.0232629 206.005 4096
EOD
$t7 << EOD
0.454208 35.945 256
0.20956 35.8455 512
0.111662 64.81 1024
0.0548617 55.7565 2048
0.0275278 228.405 4096
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
