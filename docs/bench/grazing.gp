set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
1.08958 10.9055
0.47308 11.2735
0.203914 11.592
0.001 12.1475
EOD
$t0 << EOD
0.384738 11.7605 256
0.185595 14.1825 512
0.123956 14.828 1024
0.0616393 13.241 2048
0.0318357 17.5885 4096
EOD
$t1 << EOD
0.00948297 23.6655 256
0.00203207 20.2325 512
0.00203207 25.948 1024
0.00135471 29.142 2048
0.00135471 36.378 4096
EOD
$t2 << EOD
0.001 52.4675 256
0.001 45.811 512
0.001 38.9685 1024
0.001 34.6865 2048
0.001 38.629 4096
EOD
$t3 << EOD
0.001 12.1475 ""
EOD
$t4 << EOD
2.5061 11.392 256
1.08958 10.9055 512
1.00258 12.5755 1024
0.628054 19.295 2048
0.487354 35.354 4096
EOD
$t5 << EOD
0.301113 220.719 512
0.161092 230.727 2048
EOD
$t6 << EOD
0.275284 13.912 256
0.14206 14.2825 512
0.0774872 17.8015 1024
0.0353451 25.807 2048
0.0163131 49.9365 4096
EOD
$t7 << EOD
0.47308 11.2735 256
0.203914 11.592 512
0.0985583 14.809 1024
0.0523379 22.2075 2048
0.0292276 70.64 4096
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
