set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.893912 6.744
0.508652 7.0355
0.147197 7.096
0.0789634 7.6425
0.001 8.36
EOD
$t0 << EOD
0.142379 9.121 256
0.0698492 9.5525 512
0.0338358 9.8055 1024
0.0180905 11.242 2048
0.00938023 14.1535 4096
EOD
$t1 << EOD
0.0118928 12.19 256
0.00234506 12.422 512
0.00117253 12.97 1024
0.001 16.4995 2048
0.001 15.6435 4096
EOD
$t2 << EOD
0.001 18.2745 256
0.001 18.5275 512
0.001 18.9515 1024
0.001 20.5525 2048
0.001 25.175 4096
EOD
$t3 << EOD
0.001 8.36 ""
EOD
$t4 << EOD
0.893912 6.744 256
0.508652 7.0355 512
0.269079 7.814 1024
0.125738 10.0335 2048
0.0734309 17.8115 4096
EOD
$t5 << EOD
0.0746045 112.142 512
0.0526423 119.782 2048
EOD
$t6 << EOD
0.118697 8.0075 256
0.0591806 8.573 512
0.0320212 10.069 1024
0.0147532 15.8925 2048
0.00771192 33.5205 4096
EOD
$t7 << EOD
0.147197 7.096 256
0.0789634 7.6425 512
0.0404038 9.829 1024
0.0160944 16.404 2048
0.0107296 45.2905 4096
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
