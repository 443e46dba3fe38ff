set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/bunny.png'
set title 'bunny: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.247832 19.7455
0.161332 20.2835
0.0901207 22.903
0.0563254 24.1035
0.039629 25.9035
0.0345999 27.0925
0.001 30.7695
EOD
$t0 << EOD
0.247832 19.7455 256
0.161332 20.2835 512
0.0901207 22.903 1024
0.0563254 24.1035 2048
0.0345999 27.0925 4096
EOD
$t1 << EOD
0.243608 24.4985 256
0.11426 23.7495 512
0.0653778 24.707 1024
0.039629 25.9035 2048
0.024743 31.1165 4096
EOD
$t2 << EOD
0.001 41.5265 256
0.001 33.4725 512
0.001 30.7695 1024
0.001 32.1305 2048
0.001 38.2315 4096
EOD
$t3 << EOD
0.001 49.3985 ""
EOD
$t4 << EOD
0.858085 24.4725 256
0.506262 25.1945 512
0.264321 25.215 1024
0.198795 26.531 2048
0.121374 34.433 4096
EOD
$t5 << EOD
0.372186 151.566 512
0.349 162.525 2048
EOD
$t6 << EOD
0.21815 25.3045 256
0.132664 26.7865 512
0.0758083 28.55 1024
0.0491947 36.429 2048
0.0298394 57.5135 4096
EOD
$t7 << EOD
0.25928 23.314 256
0.152625 23.983 512
0.0913329 26.6165 1024
0.0572594 39.396 2048
0.0399203 73.547 4096
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
