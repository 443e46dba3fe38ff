set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.5061 10.693
0.47308 10.758
0.203914 11.479
0.123956 12.3195
0.001 13.1945
EOD
$t0 << EOD
0.384738 14.1855 256
0.185595 14.2165 512
0.123956 12.3195 1024
0.0616393 13.312 2048
0.0318357 14.2045 4096
EOD
$t1 << EOD
0.00948297 15.717 256
0.00203207 17.7845 512
0.00203207 16.298 1024
0.00135471 20.536 2048
0.00135471 19.507 4096
EOD
$t2 << EOD
0.001 20.104 256
0.001 21.7155 512
0.001 19.6365 1024
0.001 23.547 2048
0.001 27.3055 4096
EOD
$t3 << EOD
0.001 13.1945 ""
EOD
$t4 << EOD
2.5061 10.693 256
1.08958 14.748 512
1.00258 17.419 1024
0.628054 21.8285 2048
0.487354 32.41 4096
EOD
$t5 << EOD
0.301113 187.45 512
0.161092 192.596 2048
EOD
$t6 << EOD
0.275284 13.5265 256
0.14206 14.3585 512
0.0774872 16.475 1024
0.0353451 24.5525 2048
0.0163131 50.023 4096
EOD
$t7 << EOD
0.47308 10.758 256
0.203914 11.479 512
0.0985583 13.6385 1024
0.0523379 22.7475 2048
0.0292276 68.0085 4096
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
