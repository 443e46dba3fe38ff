set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.62194 44.7045
1.47184 46.4775
0.729185 53.88
0.384264 57.8665
0.189347 63.5495
0.0443727 63.614
0.0204797 70.383
0.00790444 79.6565
0.0077248 88.2675
EOD
$t0 << EOD
2.62194 44.7045 256
1.47184 46.4775 512
0.729185 53.88 1024
0.384264 57.8665 2048
0.189347 63.5495 4096
EOD
$t1 << EOD
0.474985 63.1575 256
0.145693 64.9595 512
0.0443727 63.614 1024
0.0204797 70.383 2048
0.0104195 83.826 4096
EOD
$t2 << EOD
0.00790444 79.6565 256
0.0077248 88.2675 512
0.00790444 89.5635 1024
0.00790444 84.2625 2048
0.0077248 108.15 4096
EOD
$t3 << EOD
0.00862303 130.576 ""
EOD
$t4 << EOD
6.70935 56.2215 256
4.06977 51.7055 512
2.21902 54.929 1024
1.14077 69.3825 2048
0.591225 108.01 4096
EOD
$t5 << EOD
2.44718 417.652 512
2.08141 458.798 2048
EOD
$t6 << EOD
2.50053 58.4335 256
1.51121 58.358 512
0.723626 70.853 1024
0.403671 99.2395 2048
0.196716 179.621 4096
EOD
$t7 << EOD
3.05421 58.407 256
2.04638 51.3185 512
1.10035 56.1105 1024
0.524395 91.44 2048
0.276839 196.677 4096
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
