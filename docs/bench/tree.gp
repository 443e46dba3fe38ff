set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
4.4553 24.084
3.56798 24.529
2.6357 30.343
2.26656 34.852
1.35067 41.434
0.877788 44.769
0.647435 46.996
0.424688 65.508
0.321507 75.07
0.304663 128.568
0.185493 156.481
0.0728496 167.537
0.028424 398.958
0.0120012 668.254
EOD
$t0 << EOD
2.34277 37.2385 256
1.35067 41.434 512
0.647435 46.996 1024
0.321507 75.07 2048
0.185493 156.481 4096
EOD
$t1 << EOD
1.97473 111.941 256
1.05569 107.851 512
0.304663 128.568 1024
0.0728496 167.537 2048
0.028424 398.958 4096
EOD
$t2 << EOD
0.577323 1318.36 256
0.141699 1491.25 512
0.0212654 1743.43 1024
0.0160017 1906.39 2048
0.013054 1038.4 4096
EOD
$t3 << EOD
0.0120012 668.254 ""
EOD
$t4 << EOD
4.4553 24.084 256
3.56798 24.529 512
2.39674 64.365 1024
1.2289 69.855 2048
0.732974 113.989 4096
EOD
$t5 << EOD
2.66602 725.187 512
2.6251 608.776 2048
EOD
$t6 << EOD
2.26656 34.852 256
1.39301 44.845 512
0.688449 55.388 1024
0.336697 122.479 2048
0.186583 165.346 4096
EOD
$t7 << EOD
2.6357 30.343 256
1.70935 51.2995 512
0.877788 44.769 1024
0.424688 65.508 2048
0.229412 245.894 4096
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
