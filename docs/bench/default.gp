set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.0789634 9.4725
0.0404038 13.46
0.001 13.839
EOD
$t0 << EOD
0.142379 15.7035 256
0.0698492 16.1305 512
0.0338358 15.77 1024
0.018258 20.4865 2048
0.00954774 24.818 4096
EOD
$t1 << EOD
0.0118928 21.1415 256
0.00234506 21.518 512
0.00117253 20.016 1024
0.001 24.114 2048
0.001 24.4615 4096
EOD
$t2 << EOD
0.001 21.4315 256
0.001 28.1015 512
0.001 29.465 1024
0.001 37.1695 2048
0.001 45.0335 4096
EOD
$t3 << EOD
0.001 13.839 ""
EOD
$t4 << EOD
0.893912 11.9535 256
0.508652 12.454 512
0.269079 13.431 1024
0.125738 17.8845 2048
0.0734309 34.664 4096
EOD
$t5 << EOD
0.0746045 195.176 512
0.0526423 192.825 2048
EOD
$t6 << EOD
0.118697 14.1265 256
0.0591806 14.8855 512
0.0320212 14.604 1024
0.0147532 29.132 2048
0.00771192 70.1905 4096
EOD
$t7 << EOD
0.147197 10.093 256
0.0789634 9.4725 512
0.0404038 13.46 1024
0.0160944 23.5625 2048
0.0107296 60.417 4096
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
