set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.893912 10.816
0.147197 12.6555
0.001 12.8035
EOD
$t0 << EOD
0.142379 19.8105 256
0.0698492 14.2425 512
0.0338358 22.325 1024
0.018258 29.252 2048
0.00954774 57.4425 4096
EOD
$t1 << EOD
0.0118928 26.3075 256
0.00234506 28.3675 512
0.00117253 39.8935 1024
0.001 57.3095 2048
0.001 85.2795 4096
EOD
$t2 << EOD
0.00167504 45.7825 256
0.001 43.4825 512
0.001 61.439 1024
0.001 65.968 2048
0.001 70.2135 4096
EOD
$t3 << EOD
0.001 12.8035 ""
EOD
$t4 << EOD
0.893912 10.816 256
0.508652 15.32 512
0.269079 20.3775 1024
0.125738 21.3955 2048
0.0734309 33.587 4096
EOD
$t5 << EOD
0.0746045 233.698 512
0.0526423 288.01 2048
EOD
$t6 << EOD
0.118697 15.2545 256
0.0591806 16.0295 512
0.0320212 18.4475 1024
0.0147532 25.4635 2048
0.00771192 85.5455 4096
EOD
$t7 << EOD
0.147197 12.6555 256
0.0789634 14.3685 512
0.0404038 24.427 1024
0.0160944 35.346 2048
0.0107296 133.988 4096
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
