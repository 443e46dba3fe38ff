set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.384738 11.6505
0.185595 11.767
0.123956 12.2105
0.0616393 12.4885
0.0318357 14.981
0.00203207 15.5295
0.001 15.7485
0.001 21.741
EOD
$t0 << EOD
0.384738 11.6505 256
0.185595 11.767 512
0.123956 12.2105 1024
0.0616393 12.4885 2048
0.0318357 14.981 4096
EOD
$t1 << EOD
0.00948297 16.141 256
0.00203207 15.5295 512
0.00203207 15.898 1024
0.00135471 17.6895 2048
0.00135471 21.671 4096
EOD
$t2 << EOD
0.001 21.741 256
0.001 25.6485 512
0.001 25.956 1024
0.001 25.5855 2048
0.001 27.1445 4096
EOD
$t3 << EOD
0.001 15.7485 ""
EOD
$t4 << EOD
2.5061 11.815 256
1.08958 13.287 512
1.00258 11.981 1024
0.628054 18.4645 2048
0.487354 31.6335 4096
EOD
$t5 << EOD
0.301113 200.678 512
0.161092 221.783 2048
EOD
$t6 << EOD
0.275284 15.0225 256
0.14206 15.7835 512
0.0774872 17.271 1024
0.0353451 27.3455 2048
0.0163131 52.0575 4096
EOD
$t7 << EOD
0.47308 12.169 256
0.203914 15.2055 512
0.0985583 16.5315 1024
0.0523379 35.031 2048
0.0292276 57.634 4096
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
