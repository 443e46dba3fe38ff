set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
1.70935 25.6135
1.35067 28.3865
0.877788 31.55
0.424688 36.588
0.336697 44.337
0.321507 49.21
0.304663 69.2195
0.185493 77.4325
0.0728496 82.9655
0.028424 127.548
0.0212654 465.322
0.0120012 473.922
EOD
$t0 << EOD
2.34277 27.2145 256
1.35067 28.3865 512
0.647435 41.6975 1024
0.321507 49.21 2048
0.185493 77.4325 4096
EOD
$t1 << EOD
1.97473 65.0225 256
1.05569 63.9565 512
0.304663 69.2195 1024
0.0728496 82.9655 2048
0.028424 127.548 4096
EOD
$t2 << EOD
0.577323 399.19 256
0.141699 396.165 512
0.0212654 465.322 1024
0.0160017 544.137 2048
0.013054 594.169 4096
EOD
$t3 << EOD
0.0120012 473.922 ""
EOD
$t4 << EOD
4.4553 27.0915 256
3.56798 36.624 512
2.39674 32.4935 1024
1.2289 35.832 2048
0.732974 55.246 4096
EOD
$t5 << EOD
2.66602 256.905 512
2.6251 295.533 2048
EOD
$t6 << EOD
2.26656 29.852 256
1.39301 28.8965 512
0.688449 39.769 1024
0.336697 44.337 2048
0.186583 102.314 4096
EOD
$t7 << EOD
2.6357 29.3085 256
1.70935 25.6135 512
0.877788 31.55 1024
0.424688 36.588 2048
0.229412 98.2055 4096
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
