set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.454208 11.818
0.250744 14.2265
0.152189 14.3095
0.0193625 17.818
0.001 18.2925
EOD
$t0 << EOD
0.611273 14.909 256
0.250744 14.2265 512
0.152189 14.3095 1024
0.067575 20.139 2048
0.0271075 23.039 4096
EOD
$t1 << EOD
0.0193625 17.818 256
0.00116175 20.399 512
0.00387249 20.8305 1024
0.001 22.8515 2048
0.001 28.213 4096
EOD
$t2 << EOD
0.001 26.961 256
0.001 27.908 512
0.001 28.1095 1024
0.001 33.759 2048
0.001 49.3525 4096
EOD
$t3 << EOD
0.001 18.2925 ""
EOD
$t4 << EOD
0.783766 14.3005 256
0.424742 15.642 512
0.235343 15.471 1024
0.132211 27.0905 2048
0.0783184 51.6225 4096
EOD
$t5 << EOD
0.182808 182.062 512
0.190174 209.575 2048
EOD
$t6 << EOD
0.402448 15.0295 256
0.198122 15.7495 512
0.101387 19.066 1024
0.0517599 30.7605 2048
0.0232629 79.042 4096
EOD
$t7 << EOD
0.454208 11.818 256
0.20956 14.783 512
0.111662 19.816 1024
0.0548617 42.259 2048
0.0275278 82.5105 4096
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
