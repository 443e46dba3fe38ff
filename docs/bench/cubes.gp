set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
3.05421 40.866
2.21902 42.461
1.47184 44.691
0.384264 48.493
0.145693 67.669
0.0443727 76.5735
0.0204797 83.09
0.0104195 109.261
0.00790444 129.837
0.0077248 133.582
EOD
$t0 << EOD
2.62194 45.2625 256
1.47184 44.691 512
0.729185 53.1145 1024
0.384264 48.493 2048
0.189347 70.2925 4096
EOD
$t1 << EOD
0.474985 70.5545 256
0.145693 67.669 512
0.0443727 76.5735 1024
0.0204797 83.09 2048
0.0104195 109.261 4096
EOD
$t2 << EOD
0.00790444 227.01 256
0.0077248 166.15 512
0.00790444 155.253 1024
0.00790444 129.837 2048
0.0077248 133.582 4096
EOD
$t3 << EOD
0.00862303 137.981 ""
EOD
$t4 << EOD
6.70935 42.8985 256
4.06977 44.4365 512
2.21902 42.461 1024
1.14077 56.261 2048
0.591225 111.268 4096
EOD
$t5 << EOD
2.44718 394.983 512
2.08141 484.134 2048
EOD
$t6 << EOD
2.50053 52.7065 256
1.51121 53.6065 512
0.723626 62.902 1024
0.403671 82.924 2048
0.196716 145 4096
EOD
$t7 << EOD
3.05421 40.866 256
2.04638 57.0745 512
1.10035 51.8085 1024
0.524395 77.8295 2048
0.276839 156.65 4096
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
