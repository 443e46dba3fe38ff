set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.47308 10.027
0.275284 11.196
0.203914 12.5045
0.0985583 12.639
0.0774872 13.735
0.0616393 19.073
0.0318357 19.2085
0.001 19.558
EOD
$t0 << EOD
0.384738 17.0195 256
0.185595 20.484 512
0.123956 20.444 1024
0.0616393 19.073 2048
0.0318357 19.2085 4096
EOD
$t1 << EOD
0.00948297 36.786 256
0.00203207 23.7195 512
0.00203207 25.066 1024
0.00135471 27.581 2048
0.00135471 32.603 4096
EOD
$t2 << EOD
0.001 56.689 256
0.001 50.228 512
0.00135471 50.894 1024
0.00135471 44.7705 2048
0.001 51.5055 4096
EOD
$t3 << EOD
0.001 19.558 ""
EOD
$t4 << EOD
2.5061 13.573 256
1.08958 12.151 512
1.00258 15.848 1024
0.628054 16.881 2048
0.487354 27.32 4096
EOD
$t5 << EOD
0.301113 234.671 512
0.161092 234.386 2048
EOD
$t6 << EOD
0.275284 11.196 256
0.14206 13.9975 512
0.0774872 13.735 1024
0.0353451 20.403 2048
0.0163131 51.4155 4096
EOD
$t7 << EOD
0.47308 10.027 256
0.203914 12.5045 512
0.0985583 12.639 1024
0.0523379 19.397 2048
0.0292276 62.537 4096
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
