set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.783766 9.4705
0.235343 10.0315
0.198122 11.794
0.00116175 14.696
0.001 14.8915
EOD
$t0 << EOD
0.611273 12.816 256
0.250744 14.3255 512
0.152189 15.785 1024
0.067575 17.9845 2048
0.0271075 22.7275 4096
EOD
$t1 << EOD
0.0193625 19.565 256
0.00116175 14.696 512
0.00387249 16.0445 1024
0.001 19.135 2048
0.001 27.802 4096
EOD
$t2 << EOD
0.001 24.7935 256
0.001 21.791 512
0.001 24.1095 1024
0.001 30.793 2048
0.001 35.502 4096
EOD
$t3 << EOD
0.001 14.8915 ""
EOD
$t4 << EOD
0.783766 9.4705 256
0.424742 10.855 512
0.235343 10.0315 1024
0.132211 15.4785 2048
0.0783184 31.067 4096
EOD
$t5 << EOD
0.182808 157.157 512
0.190174 167.875 2048
EOD
$t6 << EOD
0.402448 11.461 256
0.198122 11.794 512
0.101387 19.608 1024
0.0517599 22.5735 2048
0.0232629 61.4225 4096
EOD
$t7 << EOD
0.454208 10.227 256
0.20956 14.056 512
0.111662 15.731 1024
0.0548617 28.192 2048
0.0275278 71.242 4096
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
