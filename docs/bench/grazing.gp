set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.0985583 16.4925
0.0523379 23.777
0.001 37.584
EOD
$t0 << EOD
0.384738 60.977 256
0.185595 51.74 512
0.123956 59.599 1024
0.0616393 81.4115 2048
0.0318357 137.941 4096
EOD
$t1 << EOD
0.00948297 75.817 256
0.00203207 88.719 512
0.00203207 99.7285 1024
0.00135471 98.92 2048
0.00135471 157.101 4096
EOD
$t2 << EOD
0.001 108.103 256
0.001 98.648 512
0.00135471 119.012 1024
0.00135471 145.203 2048
0.001 174.571 4096
EOD
$t3 << EOD
0.001 37.584 ""
EOD
$t4 << EOD
2.5061 27.6165 256
1.08958 30.646 512
1.00258 43.235 1024
0.628054 69.9365 2048
0.487354 63.053 4096
EOD
$t5 << EOD
0.301113 660.192 512
0.161092 782.917 2048
EOD
$t6 << EOD
0.275284 31.802 256
0.14206 28.8075 512
0.0774872 40.7995 1024
0.0353451 57.5195 2048
0.0163131 59.237 4096
EOD
$t7 << EOD
0.47308 19.8995 256
0.203914 19.8435 512
0.0985583 16.4925 1024
0.0523379 23.777 2048
0.0292276 162.453 4096
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
