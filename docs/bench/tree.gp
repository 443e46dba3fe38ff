set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
3.56798 17.1445
1.70935 22.815
1.35067 24.0845
0.647435 25.6255
0.321507 28.1825
0.304663 28.2875
0.185493 32.8765
0.0728496 34.876
0.028424 40.0425
0.00252658 65.3525
0.00231603 72.573
EOD
$t0 << EOD
2.34277 24.388 256
1.35067 24.0845 512
0.647435 25.6255 1024
0.321507 28.1825 2048
0.185493 32.8765 4096
EOD
$t1 << EOD
1.97473 29.2225 256
1.05569 28.282 512
0.304663 28.2875 1024
0.0728496 34.876 2048
0.028424 40.0425 4096
EOD
$t2 << EOD
0.00252658 73.899 256
0.00252658 65.3525 512
0.00231603 72.573 1024
0.00252658 71.1365 2048
0.00273712 81.6995 4096
EOD
$t3 << EOD
0.0120012 352.558 ""
EOD
$t4 << EOD
4.4553 21.318 256
3.56798 17.1445 512
2.39674 25.1565 1024
1.2289 27.9665 2048
0.732974 49.241 4096
EOD
$t5 << EOD
2.66602 201.853 512
2.6251 219.659 2048
EOD
$t6 << EOD
2.26656 23.3595 256
1.39301 26.894 512
0.688449 32.3165 1024
0.336697 45.7635 2048
0.186583 99.6405 4096
EOD
$t7 << EOD
2.6357 26.2235 256
1.70935 22.815 512
0.877788 28.475 1024
0.424688 50.3795 2048
0.229412 153.939 4096
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
