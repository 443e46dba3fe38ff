set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.118697 11.9445
0.0789634 13.0835
0.0591806 13.0855
0.001 13.129
EOD
$t0 << EOD
0.142379 13.16 256
0.0698492 14.5275 512
0.0338358 14.681 1024
0.018258 17.839 2048
0.00954774 22.5595 4096
EOD
$t1 << EOD
0.0118928 25.848 256
0.00234506 27.7095 512
0.00117253 25.4875 1024
0.001 30.04 2048
0.001 46.6095 4096
EOD
$t2 << EOD
0.001 26.4265 256
0.001 20.279 512
0.001 22.008 1024
0.001 27.041 2048
0.001 40.1895 4096
EOD
$t3 << EOD
0.001 13.129 ""
EOD
$t4 << EOD
0.893912 12.327 256
0.508652 13.099 512
0.269079 14.2295 1024
0.125738 16.5575 2048
0.0734309 36.0305 4096
EOD
$t5 << EOD
0.0746045 196.743 512
0.0526423 214.494 2048
EOD
$t6 << EOD
0.118697 11.9445 256
0.0591806 13.0855 512
0.0320212 17.2005 1024
0.0147532 37.3575 2048
0.00771192 66.862 4096
EOD
$t7 << EOD
0.147197 14.344 256
0.0789634 13.0835 512
0.0404038 21.773 1024
0.0160944 39.277 2048
0.0107296 91.004 4096
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
