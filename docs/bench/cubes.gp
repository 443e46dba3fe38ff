set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/cubes.png'
set title 'cubes: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
3.05421 44.847
2.62194 47.039
0.729185 47.1005
0.384264 52.2315
0.145693 65.622
0.0443727 71.617
0.0204797 80.41
0.0104195 88.036
0.00179646 93.062
EOD
$t0 << EOD
2.62194 47.039 256
1.47184 48.036 512
0.729185 47.1005 1024
0.384264 52.2315 2048
0.189347 67.076 4096
EOD
$t1 << EOD
0.474985 60.172 256
0.145693 65.622 512
0.0443727 71.617 1024
0.0204797 80.41 2048
0.0104195 88.036 4096
EOD
$t2 << EOD
0.00197611 96.949 256
0.00197611 96.0285 512
0.00179646 93.062 1024
0.00197611 98.1545 2048
0.00197611 102.236 4096
EOD
$t3 << EOD
0.00862303 147.095 ""
EOD
$t4 << EOD
6.70935 58.3955 256
4.06977 54.1755 512
2.21902 58.9825 1024
1.14077 75.6355 2048
0.591225 97.8005 4096
EOD
$t5 << EOD
2.44718 418.786 512
2.08141 463.982 2048
EOD
$t6 << EOD
2.50053 57.613 256
1.51121 55.263 512
0.723626 63.838 1024
0.403671 74.237 2048
0.196716 146.225 4096
EOD
$t7 << EOD
3.05421 44.847 256
2.04638 50.3245 512
1.10035 56.8405 1024
0.524395 84.417 2048
0.276839 164.423 4096
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
