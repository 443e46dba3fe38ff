set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.454208 8.99
0.20956 10.0005
0.198122 13.7185
0.111662 14.964
0.067575 15.6865
0.001 17.594
EOD
$t0 << EOD
0.611273 15.404 256
0.250744 15.7235 512
0.152189 17.6385 1024
0.067575 15.6865 2048
0.0271075 19.7595 4096
EOD
$t1 << EOD
0.0193625 18.364 256
0.00116175 19.8105 512
0.00387249 25.5625 1024
0.001 26.2245 2048
0.001 41.1265 4096
EOD
$t2 << EOD
0.001 27.999 256
0.001 25.717 512
0.001 27.862 1024
0.001 34.193 2048
0.001 45.588 4096
EOD
$t3 << EOD
0.001 17.594 ""
EOD
$t4 << EOD
0.783766 14.199 256
0.424742 11.896 512
0.235343 13.022 1024
0.132211 17.874 2048
0.0783184 35.9235 4096
EOD
$t5 << EOD
0.182808 157.822 512
0.190174 167.182 2048
EOD
$t6 << EOD
0.402448 12.211 256
0.198122 13.7185 512
0.101387 17.4565 1024
0.0517599 24.757 2048
0.0232629 53.0515 4096
EOD
$t7 << EOD
0.454208 8.99 256
0.20956 10.0005 512
0.111662 14.964 1024
0.0548617 23.299 2048
0.0275278 64.8785 4096
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
