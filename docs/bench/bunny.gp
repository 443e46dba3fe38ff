set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.244613 27.059
0.157711 27.5465
0.150004 30.318
0.0617568 32.6855
0.0325883 33.559
0.022329 38.2195
0.001 39.359
EOD
$t0 << EOD
0.244613 27.059 256
0.157711 27.5465 512
0.0869021 33.0005 1024
0.0539115 35.4275 2048
0.0325883 33.559 4096
EOD
$t1 << EOD
0.240389 39.7415 256
0.110639 33.6785 512
0.0617568 32.6855 1024
0.037215 42.5395 2048
0.022329 38.2195 4096
EOD
$t2 << EOD
0.001 44.271 256
0.001 39.359 512
0.001 40.528 1024
0.001 54.59 2048
0.001 56.2875 4096
EOD
$t3 << EOD
0.00382208 63.459 ""
EOD
$t4 << EOD
0.856674 31.099 256
0.503641 34.0635 512
0.260893 30.2595 1024
0.197787 36.751 2048
0.121172 58.5945 4096
EOD
$t5 << EOD
0.368759 250.99 512
0.345573 236.121 2048
EOD
$t6 << EOD
0.214723 32.128 256
0.130447 43.1405 512
0.072784 47.6525 1024
0.0473802 47.787 2048
0.0268152 80.504 4096
EOD
$t7 << EOD
0.255853 30.899 256
0.150004 30.318 512
0.0879054 34.74 1024
0.0550417 48.2535 2048
0.0389122 94.4675 4096
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
