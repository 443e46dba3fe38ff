set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.783766 11.241
0.454208 12.2425
0.20956 12.544
0.152189 14.317
0.001 15.2505
EOD
$t0 << EOD
0.611273 13.5695 256
0.250744 13.9005 512
0.152189 14.317 1024
0.067575 17.09 2048
0.0271075 24.3315 4096
EOD
$t1 << EOD
0.0193625 15.9805 256
0.00116175 20.553 512
0.00387249 21.365 1024
0.001 23.5785 2048
0.001 28.9915 4096
EOD
$t2 << EOD
0.001 23.229 256
0.001 26.433 512
0.001 26.7495 1024
0.001 30.124 2048
0.001 38.9145 4096
EOD
$t3 << EOD
0.001 15.2505 ""
EOD
$t4 << EOD
0.783766 11.241 256
0.424742 13.782 512
0.235343 13.5605 1024
0.132211 16.0345 2048
0.0783184 42.017 4096
EOD
$t5 << EOD
0.182808 176.984 512
0.190174 204.352 2048
EOD
$t6 << EOD
0.402448 16.925 256
0.198122 15.628 512
0.101387 19.75 1024
0.0517599 30.4025 2048
0.0232629 62.361 4096
EOD
$t7 << EOD
0.454208 12.2425 256
0.20956 12.544 512
0.111662 17.808 1024
0.0548617 30.3945 2048
0.0275278 122.363 4096
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
