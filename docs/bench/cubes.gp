set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.21902 46.307
1.10035 54.664
0.723626 66.3815
0.524395 74.611
0.403671 89.0175
0.384264 103.078
0.0443727 103.796
0.0204797 142.135
0.00862303 153.506
0.00844338 351.099
EOD
$t0 << EOD
2.62194 66.607 256
1.47184 72.2755 512
0.729185 94.8395 1024
0.384264 103.078 2048
0.189347 159.96 4096
EOD
$t1 << EOD
0.474985 98.7395 256
0.145693 104.01 512
0.0443727 103.796 1024
0.0204797 142.135 2048
0.0104195 209.784 4096
EOD
$t2 << EOD
0.0617984 269.113 256
0.0438337 262.769 512
0.0181443 273.178 1024
0.0113177 291.991 2048
0.00844338 351.099 4096
EOD
$t3 << EOD
0.00862303 153.506 ""
EOD
$t4 << EOD
6.70935 62.4055 256
4.06977 50.512 512
2.21902 46.307 1024
1.14077 70.113 2048
0.591225 114.675 4096
EOD
$t5 << EOD
2.44718 538.736 512
2.08141 595.881 2048
EOD
$t6 << EOD
2.50053 54.8635 256
1.51121 58.609 512
0.723626 66.3815 1024
0.403671 89.0175 2048
0.196716 154.699 4096
EOD
$t7 << EOD
3.05421 52.956 256
2.04638 58.617 512
1.10035 54.664 1024
0.524395 74.611 2048
0.276839 172.145 4096
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
