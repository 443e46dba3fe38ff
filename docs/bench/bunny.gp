set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.244613 40.236
0.157711 40.7175
0.130447 43.771
0.0539115 45.986
0.022329 50.8205
0.00362092 57.31
EOD
$t0 << EOD
0.244613 40.236 256
0.157711 40.7175 512
0.0869021 46.2085 1024
0.0539115 45.986 2048
0.0325883 54.782 4096
EOD
$t1 << EOD
0.240389 50.673 256
0.110639 47.8165 512
0.0617568 47.7265 1024
0.037215 52.3515 2048
0.022329 50.8205 4096
EOD
$t2 << EOD
0.00362092 57.31 256
0.00362092 58.1875 512
0.00382208 64.655 1024
0.00382208 65.9045 2048
0.00362092 80.737 4096
EOD
$t3 << EOD
0.00382208 85.5115 ""
EOD
$t4 << EOD
0.856674 42.826 256
0.503641 40.92 512
0.260893 45.7805 1024
0.197787 56.5375 2048
0.121172 83.54 4096
EOD
$t5 << EOD
0.368759 254.183 512
0.345573 298.262 2048
EOD
$t6 << EOD
0.214723 50.666 256
0.130447 43.771 512
0.072784 50.9665 1024
0.0473802 68.9975 2048
0.0268152 137.982 4096
EOD
$t7 << EOD
0.255853 42.549 256
0.150004 51.519 512
0.0879054 54.077 1024
0.0550417 66.5975 2048
0.0389122 159.224 4096
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
