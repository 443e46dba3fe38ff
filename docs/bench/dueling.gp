set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.783572 7.531
0.42416 7.6205
0.209754 8.3045
0.197928 9.2315
0.001 10.017
0.001 18.684
EOD
$t0 << EOD
0.611467 9.425 256
0.25055 9.6805 512
0.152383 10.097 1024
0.0677686 11.227 2048
0.0269138 13.702 4096
EOD
$t1 << EOD
0.0187816 11.6935 256
0.001 11.966 512
0.00329162 12.6625 1024
0.001 13.8405 2048
0.001 16.1065 4096
EOD
$t2 << EOD
0.001 18.684 256
0.001 19.233 512
0.001 19.678 1024
0.001 21.294 2048
0.001 25.069 4096
EOD
$t3 << EOD
0.001 10.017 ""
EOD
$t4 << EOD
0.783572 7.531 256
0.42416 7.6205 512
0.234761 8.64 1024
0.131629 10.938 2048
0.0785123 20.514 4096
EOD
$t5 << EOD
0.182614 112.418 512
0.18998 121.862 2048
EOD
$t6 << EOD
0.402254 8.3125 256
0.197928 9.2315 512
0.101194 10.466 1024
0.0519538 15.5355 2048
0.023069 34.0595 4096
EOD
$t7 << EOD
0.453626 7.7575 256
0.209754 8.3045 512
0.111468 10.896 1024
0.0546678 17.9675 2048
0.0277216 49.7455 4096
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
