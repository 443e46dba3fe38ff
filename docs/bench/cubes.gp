set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.62302 24.3225
1.4722 25.7225
0.730263 27.442
0.385342 29.7155
0.141741 33.639
0.0397019 35.024
0.0154496 40.405
0.00197611 45.0605
EOD
$t0 << EOD
2.62302 24.3225 256
1.4722 25.7225 512
0.730263 27.442 1024
0.385342 29.7155 2048
0.188988 35.1925 4096
EOD
$t1 << EOD
0.471033 31.435 256
0.141741 33.639 512
0.0397019 35.024 1024
0.0154496 40.405 2048
0.00538939 46.2655 4096
EOD
$t2 << EOD
0.00197611 45.0605 256
0.00197611 45.171 512
0.00197611 46.0045 1024
0.00197611 48.933 2048
0.00197611 54.451 4096
EOD
$t3 << EOD
0.00359293 68.5265 ""
EOD
$t4 << EOD
6.71079 27.005 256
4.07013 27.9705 512
2.21902 29.647 1024
1.14077 33.926 2048
0.591225 49.628 4096
EOD
$t5 << EOD
2.44862 256.014 512
2.08357 298 2048
EOD
$t6 << EOD
2.49874 35.2855 256
1.50869 34.782 512
0.722908 36.3705 1024
0.403312 51.4125 2048
0.196356 86.658 4096
EOD
$t7 << EOD
3.05278 28.592 256
2.04674 33.428 512
1.09963 36.6105 1024
0.524395 47.3095 2048
0.277198 85.562 4096
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
