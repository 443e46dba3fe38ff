set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.0899196 20.2715
0.0559231 21.037
0.0343988 23.5975
0.024743 32.5655
0.001 46.301
EOD
$t0 << EOD
0.24743 25.092 256
0.161332 21.3935 512
0.0899196 20.2715 1024
0.0559231 21.037 2048
0.0343988 23.5975 4096
EOD
$t1 << EOD
0.243608 23.7215 256
0.11426 22.617 512
0.0653778 25.8625 1024
0.0392267 29.276 2048
0.024743 32.5655 4096
EOD
$t2 << EOD
0.001 46.301 256
0.001 47.2245 512
0.001 47.569 1024
0.001 52.9355 2048
0.001 54.4255 4096
EOD
$t3 << EOD
0.001 55.8765 ""
EOD
$t4 << EOD
0.858085 27.4265 256
0.506262 27.224 512
0.264321 28.7825 1024
0.198795 33.867 2048
0.121374 41.4005 4096
EOD
$t5 << EOD
0.372186 170.216 512
0.349 176.34 2048
EOD
$t6 << EOD
0.21815 40.8495 256
0.132664 38.6795 512
0.0758083 43.1695 1024
0.0491947 52.512 2048
0.0298394 75.2335 4096
EOD
$t7 << EOD
0.25928 27.444 256
0.152625 37.4635 512
0.0913329 37.821 1024
0.0572594 47.1735 2048
0.0399203 85.7005 4096
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
