set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.157711 30.703
0.0325883 36.49
0.022329 48.5235
0.001 56.144
EOD
$t0 << EOD
0.244613 36.0605 256
0.157711 30.703 512
0.0869021 40.887 1024
0.0539115 37.9595 2048
0.0325883 36.49 4096
EOD
$t1 << EOD
0.240389 38.403 256
0.110639 39.8555 512
0.0617568 44.4065 1024
0.037215 44.4435 2048
0.022329 48.5235 4096
EOD
$t2 << EOD
0.001 61.4555 256
0.001 56.8385 512
0.001 57.303 1024
0.001 56.144 2048
0.001 67.0215 4096
EOD
$t3 << EOD
0.00382208 75.716 ""
EOD
$t4 << EOD
0.856674 31.6365 256
0.503641 36.1995 512
0.260893 37.8075 1024
0.197787 41.474 2048
0.121172 67.7925 4096
EOD
$t5 << EOD
0.368759 258.588 512
0.345573 280.188 2048
EOD
$t6 << EOD
0.214723 45.6415 256
0.130447 42.4335 512
0.072784 53.825 1024
0.0473802 64.5825 2048
0.0268152 101.49 4096
EOD
$t7 << EOD
0.255853 38.381 256
0.150004 37.1875 512
0.0879054 44.368 1024
0.0550417 65.2135 2048
0.0389122 125.02 4096
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
