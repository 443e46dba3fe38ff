set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.47308 12.7605
0.123956 12.849
0.0616393 16.0275
0.001 17.403
0.001 24.9985
EOD
$t0 << EOD
0.384738 16.372 256
0.185595 16.4835 512
0.123956 12.849 1024
0.0616393 16.0275 2048
0.0318357 18.4825 4096
EOD
$t1 << EOD
0.00948297 18.312 256
0.00203207 19.648 512
0.00203207 18.7215 1024
0.00135471 24.1095 2048
0.00135471 27.656 4096
EOD
$t2 << EOD
0.001 30.2665 256
0.001 29.5845 512
0.001 26.0455 1024
0.001 24.9985 2048
0.001 36.3525 4096
EOD
$t3 << EOD
0.001 17.403 ""
EOD
$t4 << EOD
2.5061 14.388 256
1.08958 16.5945 512
1.00258 15.0655 1024
0.628054 18.273 2048
0.487354 41.015 4096
EOD
$t5 << EOD
0.301113 207.375 512
0.161092 214.517 2048
EOD
$t6 << EOD
0.275284 17.3835 256
0.14206 15.2865 512
0.0774872 18.302 1024
0.0353451 25.6435 2048
0.0163131 51.931 4096
EOD
$t7 << EOD
0.47308 12.7605 256
0.203914 14.377 512
0.0985583 20.539 1024
0.0523379 25.2865 2048
0.0292276 76.941 4096
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
