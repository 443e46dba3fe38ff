set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.5061 10.2505
0.275284 10.411
0.203914 11.8985
0.123956 12.884
0.001 12.95
EOD
$t0 << EOD
0.384738 13.4025 256
0.185595 13.8225 512
0.123956 12.884 1024
0.0616393 13.189 2048
0.0318357 16.288 4096
EOD
$t1 << EOD
0.00948297 23.332 256
0.00203207 21.0885 512
0.00203207 23.6135 1024
0.00135471 23.249 2048
0.00135471 39.9385 4096
EOD
$t2 << EOD
0.001 37.9515 256
0.001 31.87 512
0.001 28.4845 1024
0.001 29.1045 2048
0.001 33.155 4096
EOD
$t3 << EOD
0.001 12.95 ""
EOD
$t4 << EOD
2.5061 10.2505 256
1.08958 10.8975 512
1.00258 13.039 1024
0.628054 16.8325 2048
0.487354 40.8525 4096
EOD
$t5 << EOD
0.301113 177.031 512
0.161092 189.502 2048
EOD
$t6 << EOD
0.275284 10.411 256
0.14206 13.399 512
0.0774872 16.718 1024
0.0353451 20.136 2048
0.0163131 49.655 4096
EOD
$t7 << EOD
0.47308 11.2255 256
0.203914 11.8985 512
0.0985583 13.9605 1024
0.0523379 23.2215 2048
0.0292276 49.8445 4096
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
