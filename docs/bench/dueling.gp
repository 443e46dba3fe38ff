set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.783766 8.59
0.454208 10.168
0.20956 10.6715
0.198122 12.6905
0.067575 12.8045
0.001 13.1575
0.001 21.7325
EOD
$t0 << EOD
0.611273 13.4065 256
0.250744 13.2085 512
0.152189 12.953 1024
0.067575 12.8045 2048
0.0271075 20.7875 4096
EOD
$t1 << EOD
0.0193625 15.6755 256
0.00116175 14.7285 512
0.00387249 15.5475 1024
0.001 22.2435 2048
0.001 21.875 4096
EOD
$t2 << EOD
0.001 21.7325 256
0.001 22.5715 512
0.001 26.0555 1024
0.001 28.5975 2048
0.001 30.5245 4096
EOD
$t3 << EOD
0.001 13.1575 ""
EOD
$t4 << EOD
0.783766 8.59 256
0.424742 12.05 512
0.235343 14.1855 1024
0.132211 14.7385 2048
0.0783184 32.499 4096
EOD
$t5 << EOD
0.182808 151.941 512
0.190174 175.394 2048
EOD
$t6 << EOD
0.402448 11.6045 256
0.198122 12.6905 512
0.101387 15.557 1024
0.0517599 23.544 2048
0.0232629 53.1815 4096
EOD
$t7 << EOD
0.454208 10.168 256
0.20956 10.6715 512
0.111662 13.8685 1024
0.0548617 22.2275 2048
0.0275278 64.0435 4096
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
