set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
3.05421 34.7675
2.04638 36.239
1.10035 44.871
0.729185 55.18
0.723626 56.514
0.524395 56.9165
0.384264 59.953
0.189347 65.043
0.145693 67.989
0.0443727 70.742
0.0204797 93.6645
0.00790444 101.844
0.0077248 113.242
EOD
$t0 << EOD
2.62194 45.798 256
1.47184 49.713 512
0.729185 55.18 1024
0.384264 59.953 2048
0.189347 65.043 4096
EOD
$t1 << EOD
0.474985 61.719 256
0.145693 67.989 512
0.0443727 70.742 1024
0.0204797 93.6645 2048
0.0104195 109.735 4096
EOD
$t2 << EOD
0.00790444 148.942 256
0.0077248 113.242 512
0.00790444 104.053 1024
0.00790444 101.844 2048
0.0077248 122.6 4096
EOD
$t3 << EOD
0.00862303 137.934 ""
EOD
$t4 << EOD
6.70935 42.494 256
4.06977 50.1915 512
2.21902 50.884 1024
1.14077 70.776 2048
0.591225 89.769 4096
EOD
$t5 << EOD
2.44718 402.337 512
2.08141 438.507 2048
EOD
$t6 << EOD
2.50053 43.621 256
1.51121 45.5775 512
0.723626 56.514 1024
0.403671 75.671 2048
0.196716 143.958 4096
EOD
$t7 << EOD
3.05421 34.7675 256
2.04638 36.239 512
1.10035 44.871 1024
0.524395 56.9165 2048
0.276839 166.811 4096
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
