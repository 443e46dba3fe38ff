set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.244613 29.273
0.157711 30.12
0.0869021 31.3465
0.0539115 39.697
0.0325883 40.093
0.022329 43.8275
0.00362092 50.1975
EOD
$t0 << EOD
0.244613 29.273 256
0.157711 30.12 512
0.0869021 31.3465 1024
0.0539115 39.697 2048
0.0325883 40.093 4096
EOD
$t1 << EOD
0.240389 37.276 256
0.110639 44.779 512
0.0617568 41.6165 1024
0.037215 48.8465 2048
0.022329 43.8275 4096
EOD
$t2 << EOD
0.00362092 50.1975 256
0.00362092 53.642 512
0.00382208 53.9095 1024
0.00382208 57.1745 2048
0.00362092 63.2415 4096
EOD
$t3 << EOD
0.00382208 71.072 ""
EOD
$t4 << EOD
0.856674 32.3255 256
0.503641 30.7005 512
0.260893 39.153 1024
0.197787 44.154 2048
0.121172 71.222 4096
EOD
$t5 << EOD
0.368759 245.049 512
0.345573 274.789 2048
EOD
$t6 << EOD
0.214723 39.4395 256
0.130447 45.516 512
0.072784 46.2785 1024
0.0473802 59.463 2048
0.0268152 110.842 4096
EOD
$t7 << EOD
0.255853 40.223 256
0.150004 46.4955 512
0.0879054 48.7835 1024
0.0550417 64.069 2048
0.0389122 154.33 4096
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
