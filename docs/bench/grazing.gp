set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.5061 13.112
0.203914 13.38
0.185595 15.426
0.0985583 15.908
0.0616393 18.779
0.00135471 19.0335
0.001 20.1955
EOD
$t0 << EOD
0.384738 14.7825 256
0.185595 15.426 512
0.123956 17.0775 1024
0.0616393 18.779 2048
0.0318357 20.1805 4096
EOD
$t1 << EOD
0.00948297 20.12 256
0.00203207 20.7065 512
0.00203207 23.55 1024
0.00135471 19.0335 2048
0.00135471 25.4465 4096
EOD
$t2 << EOD
0.001 24.7325 256
0.001 26.448 512
0.001 23.327 1024
0.001 24.7315 2048
0.001 37.141 4096
EOD
$t3 << EOD
0.001 20.1955 ""
EOD
$t4 << EOD
2.5061 13.112 256
1.08958 13.494 512
1.00258 18.7775 1024
0.628054 25.153 2048
0.487354 53.587 4096
EOD
$t5 << EOD
0.301113 211.28 512
0.161092 231.044 2048
EOD
$t6 << EOD
0.275284 15.853 256
0.14206 17.0585 512
0.0774872 18.8305 1024
0.0353451 28.573 2048
0.0163131 65.164 4096
EOD
$t7 << EOD
0.47308 13.8685 256
0.203914 13.38 512
0.0985583 15.908 1024
0.0523379 25.095 2048
0.0292276 60.821 4096
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
