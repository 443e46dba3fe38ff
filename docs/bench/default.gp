set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.147197 10.345
0.0789634 11.0425
0.0591806 12.8745
0.001 13.405
EOD
$t0 << EOD
0.142379 15.29 256
0.0698492 15.56 512
0.0338358 13.62 1024
0.018258 18.599 2048
0.00954774 25.1955 4096
EOD
$t1 << EOD
0.0118928 17.033 256
0.00234506 18.695 512
0.00117253 19.263 1024
0.001 22.8625 2048
0.001 33.1265 4096
EOD
$t2 << EOD
0.001 22.634 256
0.001 27.5775 512
0.001 26.262 1024
0.001 30.194 2048
0.001 39.2015 4096
EOD
$t3 << EOD
0.001 13.405 ""
EOD
$t4 << EOD
0.893912 12.052 256
0.508652 13.473 512
0.269079 13.5265 1024
0.125738 21.931 2048
0.0734309 32.423 4096
EOD
$t5 << EOD
0.0746045 177.741 512
0.0526423 183.379 2048
EOD
$t6 << EOD
0.118697 12.3065 256
0.0591806 12.8745 512
0.0320212 16.207 1024
0.0147532 24.709 2048
0.00771192 58.009 4096
EOD
$t7 << EOD
0.147197 10.345 256
0.0789634 11.0425 512
0.0404038 16.233 1024
0.0160944 28.767 2048
0.0107296 76.862 4096
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
