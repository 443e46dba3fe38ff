set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
4.4553 21.1435
3.56798 21.8505
2.39674 22.2275
1.70935 23.013
0.647435 23.875
0.321507 27.569
0.304663 32.8215
0.185493 34.2685
0.0728496 37.811
0.028424 41.1405
0.0113696 93.747
EOD
$t0 << EOD
2.34277 25.0755 256
1.35067 24.015 512
0.647435 23.875 1024
0.321507 27.569 2048
0.185493 34.2685 4096
EOD
$t1 << EOD
1.97473 35.2915 256
1.05569 28.5065 512
0.304663 32.8215 1024
0.0728496 37.811 2048
0.028424 41.1405 4096
EOD
$t2 << EOD
0.0124223 108.799 256
0.0113696 111.998 512
0.0113696 109.132 1024
0.0113696 106.054 2048
0.0113696 93.747 4096
EOD
$t3 << EOD
0.0120012 349.387 ""
EOD
$t4 << EOD
4.4553 21.1435 256
3.56798 21.8505 512
2.39674 22.2275 1024
1.2289 26.6885 2048
0.732974 43.811 4096
EOD
$t5 << EOD
2.66602 200.191 512
2.6251 231.975 2048
EOD
$t6 << EOD
2.26656 27.7285 256
1.39301 25.867 512
0.688449 31.0885 1024
0.336697 37.1905 2048
0.186583 71.468 4096
EOD
$t7 << EOD
2.6357 22.2355 256
1.70935 23.013 512
0.877788 27.3235 1024
0.424688 44.3635 2048
0.229412 101.751 4096
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
