set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.61781 23.9015
1.46789 24.8505
0.724514 25.8135
0.38103 28.4585
0.0397019 34.6685
0.0154496 37.9985
0.00197611 47.8305
EOD
$t0 << EOD
2.61781 23.9015 256
1.46789 24.8505 512
0.724514 25.8135 1024
0.38103 28.4585 2048
0.185036 34.8005 4096
EOD
$t1 << EOD
0.470674 33.7865 256
0.141741 34.763 512
0.0397019 34.6685 1024
0.0154496 37.9985 2048
0.00538939 53.6535 4096
EOD
$t2 << EOD
0.00197611 57.261 256
0.00197611 57.306 512
0.00197611 56.026 1024
0.00197611 47.8305 2048
0.00197611 55.394 4096
EOD
$t3 << EOD
0.00359293 76.354 ""
EOD
$t4 << EOD
6.71079 32.623 256
4.07013 33.8485 512
2.21902 35.1375 1024
1.14077 40.494 2048
0.591225 55.2685 4096
EOD
$t5 << EOD
2.44862 255.884 512
2.08357 250.416 2048
EOD
$t6 << EOD
2.49874 26.5445 256
1.50869 27.773 512
0.722908 31.3195 1024
0.403312 40.7395 2048
0.196356 74.094 4096
EOD
$t7 << EOD
3.05278 25.3795 256
2.04674 25.821 512
1.09963 29.3805 1024
0.524395 39.554 2048
0.277198 81.9645 4096
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
