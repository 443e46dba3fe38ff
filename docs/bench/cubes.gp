set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.62194 47.4
1.47184 48.766
0.729185 53.205
0.384264 61.7335
0.145693 68.731
0.0204797 73.902
0.0104195 86.9535
0.00790444 109.239
0.0077248 130.886
EOD
$t0 << EOD
2.62194 47.4 256
1.47184 48.766 512
0.729185 53.205 1024
0.384264 61.7335 2048
0.189347 78.285 4096
EOD
$t1 << EOD
0.474985 67.518 256
0.145693 68.731 512
0.0443727 74.3375 1024
0.0204797 73.902 2048
0.0104195 86.9535 4096
EOD
$t2 << EOD
0.00790444 154.823 256
0.0077248 132.32 512
0.00790444 121 1024
0.00790444 109.239 2048
0.0077248 130.886 4096
EOD
$t3 << EOD
0.00862303 146.805 ""
EOD
$t4 << EOD
6.70935 50.415 256
4.06977 53.64 512
2.21902 57.1325 1024
1.14077 66.213 2048
0.591225 104.085 4096
EOD
$t5 << EOD
2.44718 417.84 512
2.08141 490.593 2048
EOD
$t6 << EOD
2.50053 58.164 256
1.51121 68.6 512
0.723626 72.5035 1024
0.403671 101.823 2048
0.196716 173.91 4096
EOD
$t7 << EOD
3.05421 54.6415 256
2.04638 59.901 512
1.10035 67.901 1024
0.524395 94.001 2048
0.276839 184.397 4096
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
