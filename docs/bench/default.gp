set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.147197 10.504
0.0698492 12.0435
0.001 12.743
EOD
$t0 << EOD
0.142379 12.4525 256
0.0698492 12.0435 512
0.0338358 15.1005 1024
0.018258 20.526 2048
0.00954774 26.6355 4096
EOD
$t1 << EOD
0.0118928 21.6165 256
0.00234506 21.3765 512
0.00117253 18.824 1024
0.001 20.8215 2048
0.001 31.401 4096
EOD
$t2 << EOD
0.001 27.0125 256
0.001 27.6075 512
0.001 28.1075 1024
0.001 31.0165 2048
0.001 39.1125 4096
EOD
$t3 << EOD
0.001 12.743 ""
EOD
$t4 << EOD
0.893912 15.453 256
0.508652 13.2965 512
0.269079 19.1805 1024
0.125738 20.327 2048
0.0734309 38.6935 4096
EOD
$t5 << EOD
0.0746045 187.003 512
0.0526423 227.59 2048
EOD
$t6 << EOD
0.118697 12.622 256
0.0591806 14.208 512
0.0320212 20.1895 1024
0.0147532 33.4065 2048
0.00771192 62.0745 4096
EOD
$t7 << EOD
0.147197 10.504 256
0.0789634 15.501 512
0.0404038 16.8925 1024
0.0160944 36.838 2048
0.0107296 89.3875 4096
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
