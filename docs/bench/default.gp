set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.147197 8.026
0.0789634 8.0305
0.0404038 10.1875
0.0338358 10.4685
0.001 10.6665
EOD
$t0 << EOD
0.142379 9.657 256
0.0698492 11.127 512
0.0338358 10.4685 1024
0.018258 11.8735 2048
0.00954774 15.076 4096
EOD
$t1 << EOD
0.0118928 12.478 256
0.00234506 12.719 512
0.00117253 13.7145 1024
0.001 15.3375 2048
0.001 18.6695 4096
EOD
$t2 << EOD
0.001 16.034 256
0.001 16.259 512
0.001 17.879 1024
0.001 20.464 2048
0.001 26.4395 4096
EOD
$t3 << EOD
0.001 10.6665 ""
EOD
$t4 << EOD
0.893912 8.5225 256
0.508652 9.197 512
0.269079 10.14 1024
0.125738 13.194 2048
0.0734309 23.1875 4096
EOD
$t5 << EOD
0.0746045 134.756 512
0.0526423 145.587 2048
EOD
$t6 << EOD
0.118697 10.601 256
0.0591806 12.1055 512
0.0320212 11.7445 1024
0.0147532 19.3745 2048
0.00771192 37.9525 4096
EOD
$t7 << EOD
0.147197 8.026 256
0.0789634 8.0305 512
0.0404038 10.1875 1024
0.0160944 21.9165 2048
0.0107296 48.642 4096
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
