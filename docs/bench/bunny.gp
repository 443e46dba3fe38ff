set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.130447 41.274
0.072784 42.7205
0.0550417 64.9
0.0473802 88.1725
0.00382208 183.258
EOD
$t0 << EOD
0.244613 134.132 256
0.157711 161.86 512
0.0869021 187.657 1024
0.0539115 211.864 2048
0.0325883 314.025 4096
EOD
$t1 << EOD
0.240389 201.858 256
0.110639 216.38 512
0.0617568 168.926 1024
0.037215 205.841 2048
0.022329 323.678 4096
EOD
$t2 << EOD
0.0374162 355.467 256
0.0112651 321.133 512
0.00804649 315.777 1024
0.00382208 388.645 2048
0.0048279 392.027 4096
EOD
$t3 << EOD
0.00382208 183.258 ""
EOD
$t4 << EOD
0.856674 94.528 256
0.503641 60.128 512
0.260893 62.99 1024
0.197787 89.768 2048
0.121172 192.099 4096
EOD
$t5 << EOD
0.368759 801.157 512
0.345573 623.625 2048
EOD
$t6 << EOD
0.214723 65.9785 256
0.130447 41.274 512
0.072784 42.7205 1024
0.0473802 88.1725 2048
0.0268152 208.906 4096
EOD
$t7 << EOD
0.255853 61.042 256
0.150004 98.9235 512
0.0879054 106.266 1024
0.0550417 64.9 2048
0.0389122 334.188 4096
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
