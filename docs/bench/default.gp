set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.0789634 12.698
0.0591806 14.986
0.0118928 15.576
0.001 16.5605
EOD
$t0 << EOD
0.142379 14.0865 256
0.0698492 15.1815 512
0.0338358 16.59 1024
0.018258 17.245 2048
0.00954774 22.3835 4096
EOD
$t1 << EOD
0.0118928 15.576 256
0.00234506 17.982 512
0.00117253 19.643 1024
0.001 23.061 2048
0.001 30.1885 4096
EOD
$t2 << EOD
0.001 25.759 256
0.001 25.3275 512
0.001 26.675 1024
0.001 33.1115 2048
0.001 44.321 4096
EOD
$t3 << EOD
0.001 16.5605 ""
EOD
$t4 << EOD
0.893912 13.458 256
0.508652 15.0805 512
0.269079 17.6755 1024
0.125738 24.7585 2048
0.0734309 44.8135 4096
EOD
$t5 << EOD
0.0746045 196.998 512
0.0526423 226.107 2048
EOD
$t6 << EOD
0.118697 14.637 256
0.0591806 14.986 512
0.0320212 18.3905 1024
0.0147532 30.89 2048
0.00771192 87.938 4096
EOD
$t7 << EOD
0.147197 12.7685 256
0.0789634 12.698 512
0.0404038 17.153 1024
0.0160944 31.59 2048
0.0107296 126.742 4096
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
