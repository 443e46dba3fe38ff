set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.34277 27.438
1.35067 28.09
0.647435 28.4075
0.321507 30.676
0.304663 36.1895
0.185493 36.831
0.0728496 36.955
0.028424 47.941
0.0113696 70.174
EOD
$t0 << EOD
2.34277 27.438 256
1.35067 28.09 512
0.647435 28.4075 1024
0.321507 30.676 2048
0.185493 36.831 4096
EOD
$t1 << EOD
1.97473 33.822 256
1.05569 34.3145 512
0.304663 36.1895 1024
0.0728496 36.955 2048
0.028424 47.941 4096
EOD
$t2 << EOD
0.0113696 71.578 256
0.0113696 71.71 512
0.0113696 80.021 1024
0.0113696 70.174 2048
0.0113696 86.2935 4096
EOD
$t3 << EOD
0.0120012 389.778 ""
EOD
$t4 << EOD
4.4553 28.161 256
3.56798 27.671 512
2.39674 32.9965 1024
1.2289 39.994 2048
0.732974 59.8065 4096
EOD
$t5 << EOD
2.66602 218.953 512
2.6251 254.262 2048
EOD
$t6 << EOD
2.26656 28.5115 256
1.39301 33.3245 512
0.688449 33.3465 1024
0.336697 53.8035 2048
0.186583 94.0665 4096
EOD
$t7 << EOD
2.6357 27.5305 256
1.70935 28.512 512
0.877788 39.802 1024
0.424688 67.3445 2048
0.229412 134.267 4096
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
