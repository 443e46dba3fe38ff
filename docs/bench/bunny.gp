set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.856674 39.3305
0.244613 40.8355
0.157711 41.9395
0.0869021 44.558
0.0617568 47.5405
0.0539115 49.873
0.037215 53.31
0.0325883 56.2235
0.022329 59.3025
0.00362092 68.157
EOD
$t0 << EOD
0.244613 40.8355 256
0.157711 41.9395 512
0.0869021 44.558 1024
0.0539115 49.873 2048
0.0325883 56.2235 4096
EOD
$t1 << EOD
0.240389 46.902 256
0.110639 47.947 512
0.0617568 47.5405 1024
0.037215 53.31 2048
0.022329 59.3025 4096
EOD
$t2 << EOD
0.00362092 78.48 256
0.00362092 68.157 512
0.00382208 69.9415 1024
0.00382208 72.2685 2048
0.00362092 78.719 4096
EOD
$t3 << EOD
0.00382208 91.804 ""
EOD
$t4 << EOD
0.856674 39.3305 256
0.503641 42.155 512
0.260893 47.389 1024
0.197787 56.498 2048
0.121172 72.306 4096
EOD
$t5 << EOD
0.368759 267.703 512
0.345573 306.25 2048
EOD
$t6 << EOD
0.214723 50.135 256
0.130447 49.546 512
0.072784 55.399 1024
0.0473802 67.9425 2048
0.0268152 126.901 4096
EOD
$t7 << EOD
0.255853 49.6825 256
0.150004 46.379 512
0.0879054 55.1825 1024
0.0550417 82.423 2048
0.0389122 133.154 4096
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
