set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.783766 9.2615
0.20956 10.2705
0.001 11.2865
0.001 25.227
EOD
$t0 << EOD
0.611273 14.3185 256
0.250744 13.4175 512
0.152189 13.7475 1024
0.067575 16.062 2048
0.0271075 19.614 4096
EOD
$t1 << EOD
0.0193625 13.4515 256
0.00116175 14.5615 512
0.00387249 19.0995 1024
0.001 21.783 2048
0.001 28.1525 4096
EOD
$t2 << EOD
0.001 27.278 256
0.001 26.1065 512
0.001 26.49 1024
0.001 25.227 2048
0.001 35.041 4096
EOD
$t3 << EOD
0.001 11.2865 ""
EOD
$t4 << EOD
0.783766 9.2615 256
0.424742 10.3475 512
0.235343 13.066 1024
0.132211 18.9535 2048
0.0783184 30.5435 4096
EOD
$t5 << EOD
0.182808 162.361 512
0.190174 197.805 2048
EOD
$t6 << EOD
0.402448 15.7275 256
0.198122 16.0615 512
0.101387 16.3405 1024
0.0517599 27.306 2048
0.0232629 63.204 4096
EOD
$t7 << EOD
0.454208 12.9055 256
0.20956 10.2705 512
0.111662 18.0555 1024
0.0548617 30.349 2048
0.0275278 79.414 4096
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
