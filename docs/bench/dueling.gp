set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.453626 7.394
0.42416 7.632
0.209754 7.932
0.152383 8.6555
0.001 9.5295
0.001 14.171
EOD
$t0 << EOD
0.611467 8.086 256
0.25055 8.3565 512
0.152383 8.6555 1024
0.0677686 9.74 2048
0.0269138 12.6075 4096
EOD
$t1 << EOD
0.0187816 10.6655 256
0.001 10.8275 512
0.00329162 11.59 1024
0.001 12.492 2048
0.001 17.2725 4096
EOD
$t2 << EOD
0.001 14.171 256
0.001 14.644 512
0.001 15.6815 1024
0.001 16.3805 2048
0.001 21.1205 4096
EOD
$t3 << EOD
0.001 9.5295 ""
EOD
$t4 << EOD
0.783572 7.612 256
0.42416 7.632 512
0.234761 8.384 1024
0.131629 12.4105 2048
0.0785123 24.072 4096
EOD
$t5 << EOD
0.182614 122.652 512
0.18998 132.029 2048
EOD
$t6 << EOD
0.402254 9.918 256
0.197928 10.8215 512
0.101194 12.351 1024
0.0519538 18.5785 2048
0.023069 38.2105 4096
EOD
$t7 << EOD
0.453626 7.394 256
0.209754 7.932 512
0.111468 10.38 1024
0.0546678 17.5455 2048
0.0277216 46.1665 4096
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
