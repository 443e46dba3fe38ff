set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.118697 14.195
0.001 16.36
EOD
$t0 << EOD
0.142379 27.5655 256
0.0698492 32.5575 512
0.0338358 33.388 1024
0.018258 54.4045 2048
0.00954774 93.62 4096
EOD
$t1 << EOD
0.0118928 41.124 256
0.00234506 39.0385 512
0.00117253 43.2475 1024
0.001 63.0245 2048
0.001 120.778 4096
EOD
$t2 << EOD
0.00167504 36.515 256
0.001 36.81 512
0.001 38.29 1024
0.001 42.425 2048
0.001 109.753 4096
EOD
$t3 << EOD
0.001 16.36 ""
EOD
$t4 << EOD
0.893912 15.0285 256
0.508652 16.3785 512
0.269079 19.3435 1024
0.125738 29.9035 2048
0.0734309 55.685 4096
EOD
$t5 << EOD
0.0746045 392.547 512
0.0526423 432.418 2048
EOD
$t6 << EOD
0.118697 14.195 256
0.0591806 23.3055 512
0.0320212 25.059 1024
0.0147532 47.8495 2048
0.00771192 116.011 4096
EOD
$t7 << EOD
0.147197 19.6935 256
0.0789634 24.243 512
0.0404038 36.003 1024
0.0160944 56.963 2048
0.0107296 152.61 4096
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
