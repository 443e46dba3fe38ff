set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.5061 9.0675
1.08958 10.149
0.47308 11.696
0.275284 12.427
0.14206 13.231
0.0985583 16.247
0.0774872 17.274
0.001 18.3865
EOD
$t0 << EOD
0.384738 18.066 256
0.185595 19.4845 512
0.123956 22.753 1024
0.0616393 26.8465 2048
0.0318357 37.332 4096
EOD
$t1 << EOD
0.00948297 23.143 256
0.00203207 25.791 512
0.00203207 26.3045 1024
0.00135471 32.219 2048
0.00135471 69.0475 4096
EOD
$t2 << EOD
0.001 44.833 256
0.001 44.896 512
0.00135471 43.266 1024
0.00135471 55.005 2048
0.001 72.261 4096
EOD
$t3 << EOD
0.001 18.3865 ""
EOD
$t4 << EOD
2.5061 9.0675 256
1.08958 10.149 512
1.00258 13.6565 1024
0.628054 25.276 2048
0.487354 30.278 4096
EOD
$t5 << EOD
0.301113 227.944 512
0.161092 285.077 2048
EOD
$t6 << EOD
0.275284 12.427 256
0.14206 13.231 512
0.0774872 17.274 1024
0.0353451 22.6385 2048
0.0163131 57.4975 4096
EOD
$t7 << EOD
0.47308 11.696 256
0.203914 13.49 512
0.0985583 16.247 1024
0.0523379 26.333 2048
0.0292276 58.7505 4096
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
