set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.6357 21.2535
0.647435 22.4195
0.321507 26.845
0.185493 31.099
0.0728496 35.817
0.028424 47.041
0.00231603 53.6015
EOD
$t0 << EOD
2.34277 24.156 256
1.35067 24.0935 512
0.647435 22.4195 1024
0.321507 26.845 2048
0.185493 31.099 4096
EOD
$t1 << EOD
1.97473 28.98 256
1.05569 31.1435 512
0.304663 31.572 1024
0.0728496 35.817 2048
0.028424 47.041 4096
EOD
$t2 << EOD
0.00252658 58.391 256
0.00252658 63.768 512
0.00231603 53.6015 1024
0.00252658 61.3605 2048
0.00273712 64.779 4096
EOD
$t3 << EOD
0.0120012 333.527 ""
EOD
$t4 << EOD
4.4553 22.8715 256
3.56798 22.905 512
2.39674 26.265 1024
1.2289 27.9935 2048
0.732974 45.456 4096
EOD
$t5 << EOD
2.66602 200.476 512
2.6251 241.484 2048
EOD
$t6 << EOD
2.26656 24.4815 256
1.39301 26.8675 512
0.688449 29.1565 1024
0.336697 49.9795 2048
0.186583 72.5615 4096
EOD
$t7 << EOD
2.6357 21.2535 256
1.70935 28.028 512
0.877788 28.8705 1024
0.424688 36.564 2048
0.229412 87.8545 4096
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
