set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.0869021 27.9305
0.0539115 38.113
0.0325883 41.4395
0.022329 58.1425
0.00382208 65.373
0.00362092 78.941
EOD
$t0 << EOD
0.244613 32.5495 256
0.157711 34.376 512
0.0869021 27.9305 1024
0.0539115 38.113 2048
0.0325883 41.4395 4096
EOD
$t1 << EOD
0.240389 43.562 256
0.110639 48.8455 512
0.0617568 50.834 1024
0.037215 50.428 2048
0.022329 58.1425 4096
EOD
$t2 << EOD
0.00362092 88.3205 256
0.00362092 78.941 512
0.00382208 71.815 1024
0.00382208 70.257 2048
0.00362092 88.939 4096
EOD
$t3 << EOD
0.00382208 65.373 ""
EOD
$t4 << EOD
0.856674 35.7775 256
0.503641 31.435 512
0.260893 33.283 1024
0.197787 41.584 2048
0.121172 68.5365 4096
EOD
$t5 << EOD
0.368759 242.047 512
0.345573 267.935 2048
EOD
$t6 << EOD
0.214723 39.8235 256
0.130447 43.116 512
0.072784 46.9415 1024
0.0473802 49.799 2048
0.0268152 90.332 4096
EOD
$t7 << EOD
0.255853 42.08 256
0.150004 43.288 512
0.0879054 50.4045 1024
0.0550417 55.6275 2048
0.0389122 153.599 4096
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
