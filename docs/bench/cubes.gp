set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
6.70935 92.0515
2.21902 123.582
1.10035 125.991
0.729185 137.948
0.524395 159.951
0.384264 221.099
0.276839 221.872
0.145693 260.119
0.0443727 303.268
0.00862303 305.775
0.00844338 808.077
EOD
$t0 << EOD
2.62194 133.244 256
1.47184 158.515 512
0.729185 137.948 1024
0.384264 221.099 2048
0.189347 392.989 4096
EOD
$t1 << EOD
0.474985 290.934 256
0.145693 260.119 512
0.0443727 303.268 1024
0.0204797 439.145 2048
0.0104195 665.61 4096
EOD
$t2 << EOD
0.0617984 530.298 256
0.0438337 550.332 512
0.0181443 558.683 1024
0.0113177 632.143 2048
0.00844338 808.077 4096
EOD
$t3 << EOD
0.00862303 305.775 ""
EOD
$t4 << EOD
6.70935 92.0515 256
4.06977 125.925 512
2.21902 123.582 1024
1.14077 209.577 2048
0.591225 261.208 4096
EOD
$t5 << EOD
2.44718 1376.46 512
2.08141 1901.98 2048
EOD
$t6 << EOD
2.50053 158.413 256
1.51121 126.731 512
0.723626 168.808 1024
0.403671 288.029 2048
0.196716 536.025 4096
EOD
$t7 << EOD
3.05421 132.001 256
2.04638 176.159 512
1.10035 125.991 1024
0.524395 159.951 2048
0.276839 221.872 4096
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
