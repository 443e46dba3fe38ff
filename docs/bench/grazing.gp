set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
1.08958 9.682
0.203914 9.7005
0.0985583 11.6965
0.001 13.0755
0.001 19.7515
EOD
$t0 << EOD
0.384738 11.99 256
0.185595 12.5655 512
0.123956 14.0015 1024
0.0616393 13.257 2048
0.0318357 15.298 4096
EOD
$t1 << EOD
0.00948297 15.6355 256
0.00203207 16.786 512
0.00203207 17.3185 1024
0.00135471 22.45 2048
0.00135471 22.8025 4096
EOD
$t2 << EOD
0.001 26.1205 256
0.001 25.966 512
0.001 19.7515 1024
0.001 22.904 2048
0.001 26.949 4096
EOD
$t3 << EOD
0.001 13.0755 ""
EOD
$t4 << EOD
2.5061 9.6865 256
1.08958 9.682 512
1.00258 12.3565 1024
0.628054 15.868 2048
0.487354 26.6305 4096
EOD
$t5 << EOD
0.301113 183.278 512
0.161092 193.859 2048
EOD
$t6 << EOD
0.275284 10.3785 256
0.14206 13.409 512
0.0774872 15.3095 1024
0.0353451 20.553 2048
0.0163131 42.718 4096
EOD
$t7 << EOD
0.47308 10.9455 256
0.203914 9.7005 512
0.0985583 11.6965 1024
0.0523379 19.4625 2048
0.0292276 48.255 4096
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
