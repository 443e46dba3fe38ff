set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.157711 24.378
0.0869021 27.917
0.0539115 28.638
0.0325883 33.121
0.00382208 44.707
0.00362092 57.86
EOD
$t0 << EOD
0.244613 28.034 256
0.157711 24.378 512
0.0869021 27.917 1024
0.0539115 28.638 2048
0.0325883 33.121 4096
EOD
$t1 << EOD
0.240389 43.869 256
0.110639 35.652 512
0.0617568 45.203 1024
0.037215 55.17 2048
0.022329 67.095 4096
EOD
$t2 << EOD
0.00362092 68.948 256
0.00362092 58.893 512
0.00382208 44.707 1024
0.00382208 52.469 2048
0.00362092 57.86 4096
EOD
$t3 << EOD
0.00382208 81.4085 ""
EOD
$t4 << EOD
0.856674 33.518 256
0.503641 36.837 512
0.260893 38.973 1024
0.197787 45.6925 2048
0.121172 61.7925 4096
EOD
$t5 << EOD
0.368759 232.19 512
0.345573 256.974 2048
EOD
$t6 << EOD
0.214723 41.025 256
0.130447 40.873 512
0.072784 42.138 1024
0.0473802 50.2565 2048
0.0268152 85.124 4096
EOD
$t7 << EOD
0.255853 28.141 256
0.150004 38.7655 512
0.0879054 38.324 1024
0.0550417 45.6025 2048
0.0389122 92.28 4096
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
