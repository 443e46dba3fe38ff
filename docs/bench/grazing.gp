set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.5061 11.6625
0.203914 13.753
0.185595 15.488
0.14206 16.873
0.123956 18.185
0.0616393 18.3015
0.001 20.2475
EOD
$t0 << EOD
0.384738 16.884 256
0.185595 15.488 512
0.123956 18.185 1024
0.0616393 18.3015 2048
0.0318357 23.0505 4096
EOD
$t1 << EOD
0.00948297 22.6115 256
0.00203207 21.691 512
0.00203207 22.189 1024
0.00135471 25.5885 2048
0.00135471 28.9175 4096
EOD
$t2 << EOD
0.001 40.4615 256
0.001 33.343 512
0.001 32.2845 1024
0.001 34.785 2048
0.001 40.628 4096
EOD
$t3 << EOD
0.001 20.2475 ""
EOD
$t4 << EOD
2.5061 11.6625 256
1.08958 14.8165 512
1.00258 17.231 1024
0.628054 20.271 2048
0.487354 48.3285 4096
EOD
$t5 << EOD
0.301113 240.51 512
0.161092 234.615 2048
EOD
$t6 << EOD
0.275284 18.1745 256
0.14206 16.873 512
0.0774872 19.662 1024
0.0353451 34.3005 2048
0.0163131 56.0945 4096
EOD
$t7 << EOD
0.47308 14.468 256
0.203914 13.753 512
0.0985583 20.634 1024
0.0523379 32.7545 2048
0.0292276 67.4885 4096
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
