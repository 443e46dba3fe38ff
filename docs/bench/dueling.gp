set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/dueling.png'
set title 'dueling: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.454208 8.9785
0.424742 10.4775
0.20956 10.6295
0.111662 11.9555
0.067575 14.67
0.001 15.5975
0.001 22.7225
0.001 25.78
EOD
$t0 << EOD
0.611273 11.657 256
0.250744 12.501 512
0.152189 13.771 1024
0.067575 14.67 2048
0.0271075 22.5205 4096
EOD
$t1 << EOD
0.0193625 19.726 256
0.00116175 19.3895 512
0.00387249 20.865 1024
0.001 22.036 2048
0.001 23.042 4096
EOD
$t2 << EOD
0.001 26.117 256
0.001 25.78 512
0.001 22.7225 1024
0.001 29.239 2048
0.001 36.7275 4096
EOD
$t3 << EOD
0.001 15.5975 ""
EOD
$t4 << EOD
0.783766 13.3165 256
0.424742 10.4775 512
0.235343 13.733 1024
0.132211 17.814 2048
0.0783184 34.076 4096
EOD
$t5 << EOD
0.182808 150.381 512
0.190174 171.907 2048
EOD
$t6 << EOD
0.402448 12.503 256
0.198122 12.9825 512
0.101387 15.5645 1024
0.0517599 21.521 2048
0.0232629 41.895 4096
EOD
$t7 << EOD
0.454208 8.9785 256
0.20956 10.6295 512
0.111662 11.9555 1024
0.0548617 27.2385 2048
0.0275278 64.802 4096
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
