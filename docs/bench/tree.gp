set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
4.45509 12.944
3.56946 13.409
2.3415 13.967
1.34877 14.14
0.644698 14.7175
0.319612 15.6105
0.29961 18.3425
0.179176 18.385
0.0661121 19.4045
0.0202126 24.511
0.00210548 34.4895
EOD
$t0 << EOD
2.3415 13.967 256
1.34877 14.14 512
0.644698 14.7175 1024
0.319612 15.6105 2048
0.179176 18.385 4096
EOD
$t1 << EOD
1.97536 17.5165 256
1.05358 17.033 512
0.29961 18.3425 1024
0.0661121 19.4045 2048
0.0202126 24.511 4096
EOD
$t2 << EOD
0.00210548 40.727 256
0.00252658 40.5695 512
0.00231603 34.9165 1024
0.00210548 34.4895 2048
0.00231603 38.5335 4096
EOD
$t3 << EOD
0.00336877 155.219 ""
EOD
$t4 << EOD
4.45509 12.944 256
3.56946 13.409 512
2.39441 14.0805 1024
1.22996 16.611 2048
0.734458 24.5385 4096
EOD
$t5 << EOD
2.6658 128.329 512
2.62531 136.262 2048
EOD
$t6 << EOD
2.2655 14.34 256
1.39407 14.899 512
0.687813 17.2845 1024
0.33691 23.535 2048
0.187219 44.762 4096
EOD
$t7 << EOD
2.63464 14.53 256
1.71041 14.198 512
0.877576 18.174 1024
0.426597 26.999 2048
0.230048 59.2675 4096
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
