set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.50678 7.989
1.0889 8.186
0.385415 9.0885
0.124633 9.242
0.060962 9.937
0.001 11.437
EOD
$t0 << EOD
0.385415 9.0885 256
0.184918 9.2775 512
0.124633 9.242 1024
0.060962 9.937 2048
0.0311583 11.5395 4096
EOD
$t1 << EOD
0.00880562 12.0855 256
0.00135471 12.1415 512
0.00135471 12.527 1024
0.001 13.106 2048
0.001 14.6835 4096
EOD
$t2 << EOD
0.001 15.1595 256
0.001 15.6075 512
0.001 15.389 1024
0.001 17.09 2048
0.001 19.6125 4096
EOD
$t3 << EOD
0.001 11.437 ""
EOD
$t4 << EOD
2.50678 7.989 256
1.0889 8.186 512
1.00326 9.8585 1024
0.628734 10.9185 2048
0.488034 19.2165 4096
EOD
$t5 << EOD
0.300433 130.04 512
0.161772 136.292 2048
EOD
$t6 << EOD
0.274604 10.4035 256
0.14138 10.816 512
0.078167 12.4615 1024
0.0346653 16.9775 2048
0.0169928 34.3445 4096
EOD
$t7 << EOD
0.4724 9.146 256
0.203234 10.4365 512
0.099238 11.4245 1024
0.0530176 15.7455 2048
0.0285479 34.001 4096
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
