set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/grazing.png'
set title 'grazing: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.4724 8.2055
0.203234 8.529
0.14138 9.644
0.099238 9.952
0.060962 10.9275
0.0311583 12.192
0.001 12.267
EOD
$t0 << EOD
0.38406 10.3055 256
0.184918 10.141 512
0.122601 10.222 1024
0.060962 10.9275 2048
0.0311583 12.192 4096
EOD
$t1 << EOD
0.00880562 13.1235 256
0.00135471 13.471 512
0.00135471 13.7775 1024
0.001 14.6875 2048
0.001 15.8935 4096
EOD
$t2 << EOD
0.001 21.839 256
0.001 22.721 512
0.001 23.5695 1024
0.001 23.519 2048
0.001 26.1485 4096
EOD
$t3 << EOD
0.001 12.267 ""
EOD
$t4 << EOD
2.50678 8.824 256
1.0889 9.557 512
1.00326 10.0965 1024
0.628734 11.5075 2048
0.488034 20.8815 4096
EOD
$t5 << EOD
0.300433 131.712 512
0.161772 138.648 2048
EOD
$t6 << EOD
0.274604 9.63 256
0.14138 9.644 512
0.078167 11.378 1024
0.0346653 15.3875 2048
0.0169928 31.4075 4096
EOD
$t7 << EOD
0.4724 8.2055 256
0.203234 8.529 512
0.099238 9.952 1024
0.0530176 14.0545 2048
0.0285479 32.4195 4096
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
