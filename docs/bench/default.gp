set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.147197 10.7145
0.001 12.404
EOD
$t0 << EOD
0.142379 14.966 256
0.0698492 14.392 512
0.0338358 16.0575 1024
0.018258 19.12 2048
0.00954774 26.794 4096
EOD
$t1 << EOD
0.0118928 17.3645 256
0.00234506 17.751 512
0.00117253 21.8745 1024
0.001 24.115 2048
0.001 28.7235 4096
EOD
$t2 << EOD
0.001 22.2055 256
0.001 26.315 512
0.001 28.0745 1024
0.001 31.091 2048
0.001 43.3885 4096
EOD
$t3 << EOD
0.001 12.404 ""
EOD
$t4 << EOD
0.893912 13.9565 256
0.508652 12.669 512
0.269079 15.0025 1024
0.125738 25.154 2048
0.0734309 44.838 4096
EOD
$t5 << EOD
0.0746045 192.143 512
0.0526423 219.584 2048
EOD
$t6 << EOD
0.118697 14.619 256
0.0591806 16.3845 512
0.0320212 20.432 1024
0.0147532 35.714 2048
0.00771192 72.2415 4096
EOD
$t7 << EOD
0.147197 10.7145 256
0.0789634 14.16 512
0.0404038 19.581 1024
0.0160944 31.514 2048
0.0107296 91.314 4096
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
