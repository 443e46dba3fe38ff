set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.214723 34.2565
0.0539115 35.909
0.0325883 44.566
0.022329 51.4515
0.001 58.405
EOD
$t0 << EOD
0.244613 38.8295 256
0.157711 39.5245 512
0.0869021 39.5315 1024
0.0539115 35.909 2048
0.0325883 44.566 4096
EOD
$t1 << EOD
0.240389 39.926 256
0.110639 40.203 512
0.0617568 43.56 1024
0.037215 45.3045 2048
0.022329 51.4515 4096
EOD
$t2 << EOD
0.001 64.053 256
0.001 58.405 512
0.001 62.117 1024
0.001 63.576 2048
0.001 84.5395 4096
EOD
$t3 << EOD
0.00382208 91.004 ""
EOD
$t4 << EOD
0.856674 41.104 256
0.503641 43.4275 512
0.260893 44.6725 1024
0.197787 47.2005 2048
0.121172 64.5825 4096
EOD
$t5 << EOD
0.368759 247.243 512
0.345573 249.609 2048
EOD
$t6 << EOD
0.214723 34.2565 256
0.130447 46.6855 512
0.072784 49.0705 1024
0.0473802 59.2115 2048
0.0268152 97.714 4096
EOD
$t7 << EOD
0.255853 39.024 256
0.150004 42.828 512
0.0879054 50.0955 1024
0.0550417 58.105 2048
0.0389122 101.63 4096
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
