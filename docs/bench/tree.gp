set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.34172 13.76
1.34961 13.8135
0.648067 15.221
0.29982 15.6445
0.186124 18.053
0.0659015 19.133
0.0202126 24.509
0.00210548 39.8105
EOD
$t0 << EOD
2.34172 13.76 256
1.34961 13.8135 512
0.648067 15.221 1024
0.321296 15.8345 2048
0.186124 18.053 4096
EOD
$t1 << EOD
1.97536 16.2185 256
1.05337 16.614 512
0.29982 15.6445 1024
0.0659015 19.133 2048
0.0202126 24.509 4096
EOD
$t2 << EOD
0.00210548 42.2425 256
0.00252658 40.555 512
0.00231603 41.982 1024
0.00210548 39.8105 2048
0.00231603 44.6545 4096
EOD
$t3 << EOD
0.00336877 197.272 ""
EOD
$t4 << EOD
4.45509 16.6385 256
3.56946 15.58 512
2.39441 18.326 1024
1.22996 21.646 2048
0.734458 29.8975 4096
EOD
$t5 << EOD
2.6658 136.059 512
2.62531 148.761 2048
EOD
$t6 << EOD
2.2655 16.175 256
1.39407 17.2705 512
0.687813 19.5425 1024
0.33691 26.721 2048
0.187219 43.3885 4096
EOD
$t7 << EOD
2.63464 14.866 256
1.71041 15.8555 512
0.877576 18.3815 1024
0.426597 27.2635 2048
0.230048 61.687 4096
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
