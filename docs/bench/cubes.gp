set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
3.05421 37.5635
2.04638 37.698
1.51121 40.9635
1.10035 46.748
0.729185 52.066
0.384264 55.6155
0.189347 74.4175
0.145693 74.796
0.0443727 81.6275
0.0204797 90.271
0.0104195 120.715
0.00808409 140.941
EOD
$t0 << EOD
2.62194 55.8845 256
1.47184 53.038 512
0.729185 52.066 1024
0.384264 55.6155 2048
0.189347 74.4175 4096
EOD
$t1 << EOD
0.474985 71.242 256
0.145693 74.796 512
0.0443727 81.6275 1024
0.0204797 90.271 2048
0.0104195 120.715 4096
EOD
$t2 << EOD
0.0612594 200.129 256
0.0434744 191.834 512
0.017785 144.426 1024
0.0111381 147.567 2048
0.00808409 140.941 4096
EOD
$t3 << EOD
0.00862303 149.856 ""
EOD
$t4 << EOD
6.70935 55.341 256
4.06977 52.708 512
2.21902 58.1005 1024
1.14077 63.412 2048
0.591225 95.625 4096
EOD
$t5 << EOD
2.44718 541.904 512
2.08141 564.99 2048
EOD
$t6 << EOD
2.50053 46.2465 256
1.51121 40.9635 512
0.723626 59.5775 1024
0.403671 77.701 2048
0.196716 140.237 4096
EOD
$t7 << EOD
3.05421 37.5635 256
2.04638 37.698 512
1.10035 46.748 1024
0.524395 67.2725 2048
0.276839 142.363 4096
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
