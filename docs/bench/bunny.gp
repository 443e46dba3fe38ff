set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.214723 43.525
0.157711 44.3135
0.0869021 46.958
0.0539115 53.5745
0.0473802 58.078
0.037215 78.525
0.0325883 80.864
0.00382208 104.234
EOD
$t0 << EOD
0.244613 45.3405 256
0.157711 44.3135 512
0.0869021 46.958 1024
0.0539115 53.5745 2048
0.0325883 80.864 4096
EOD
$t1 << EOD
0.240389 53.927 256
0.110639 55.844 512
0.0617568 65.828 1024
0.037215 78.525 2048
0.022329 107.445 4096
EOD
$t2 << EOD
0.0374162 185.251 256
0.0112651 144.693 512
0.00804649 199.413 1024
0.00382208 212.668 2048
0.0048279 249.088 4096
EOD
$t3 << EOD
0.00382208 104.234 ""
EOD
$t4 << EOD
0.856674 46.1925 256
0.503641 44.08 512
0.260893 48.0505 1024
0.197787 53.77 2048
0.121172 77.4265 4096
EOD
$t5 << EOD
0.368759 294.795 512
0.345573 334.19 2048
EOD
$t6 << EOD
0.214723 43.525 256
0.130447 55.0205 512
0.072784 60.985 1024
0.0473802 58.078 2048
0.0268152 104.618 4096
EOD
$t7 << EOD
0.255853 45.379 256
0.150004 47.755 512
0.0879054 56.772 1024
0.0550417 74.255 2048
0.0389122 121.533 4096
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
