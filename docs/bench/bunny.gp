set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.157711 28.761
0.0539115 32.6495
0.0325883 39.0775
0.022329 52.3795
0.00382208 81.851
EOD
$t0 << EOD
0.244613 37.287 256
0.157711 28.761 512
0.0869021 35.796 1024
0.0539115 32.6495 2048
0.0325883 39.0775 4096
EOD
$t1 << EOD
0.240389 41.9595 256
0.110639 50.541 512
0.0617568 49.2035 1024
0.037215 52.356 2048
0.022329 52.3795 4096
EOD
$t2 << EOD
0.037215 103.742 256
0.0110639 93.413 512
0.00804649 106.479 1024
0.00382208 106.998 2048
0.00462673 94.915 4096
EOD
$t3 << EOD
0.00382208 81.851 ""
EOD
$t4 << EOD
0.856674 30.006 256
0.503641 36.6115 512
0.260893 34.223 1024
0.197787 35.427 2048
0.121172 50.619 4096
EOD
$t5 << EOD
0.368759 244.047 512
0.345573 264.175 2048
EOD
$t6 << EOD
0.214723 49.834 256
0.130447 56.494 512
0.072784 51.205 1024
0.0473802 65.237 2048
0.0268152 114.195 4096
EOD
$t7 << EOD
0.255853 39.2985 256
0.150004 42.156 512
0.0879054 53.453 1024
0.0550417 57.3605 2048
0.0389122 128.014 4096
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
