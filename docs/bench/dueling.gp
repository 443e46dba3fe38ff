set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.783766 7.3145
0.424742 9.6495
0.235343 9.746
0.20956 11.187
0.067575 11.37
0.001 13.644
EOD
$t0 << EOD
0.611273 11.486 256
0.250744 10.059 512
0.152189 11.9155 1024
0.067575 11.37 2048
0.0271075 18.327 4096
EOD
$t1 << EOD
0.0193625 17.12 256
0.00116175 19.1735 512
0.00387249 16.3215 1024
0.001 23.201 2048
0.001 33.479 4096
EOD
$t2 << EOD
0.001 19.3405 256
0.001 18.116 512
0.001 16.8615 1024
0.001 28.3675 2048
0.001 33.4705 4096
EOD
$t3 << EOD
0.001 13.644 ""
EOD
$t4 << EOD
0.783766 7.3145 256
0.424742 9.6495 512
0.235343 9.746 1024
0.132211 13.599 2048
0.0783184 26.132 4096
EOD
$t5 << EOD
0.182808 171.866 512
0.190174 166.166 2048
EOD
$t6 << EOD
0.402448 12.015 256
0.198122 11.783 512
0.101387 14.3045 1024
0.0517599 24.6325 2048
0.0232629 45.5155 4096
EOD
$t7 << EOD
0.454208 9.9535 256
0.20956 11.187 512
0.111662 20.028 1024
0.0548617 28.9475 2048
0.0275278 61.2615 4096
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
