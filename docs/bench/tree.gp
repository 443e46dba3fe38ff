set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
2.34277 27.683
1.35067 27.7895
0.647435 27.911
0.321507 33.961
0.304663 38.303
0.185493 41.052
0.0728496 42.749
0.028424 50.818
0.0113696 97.0445
EOD
$t0 << EOD
2.34277 27.683 256
1.35067 27.7895 512
0.647435 27.911 1024
0.321507 33.961 2048
0.185493 41.052 4096
EOD
$t1 << EOD
1.97473 33.925 256
1.05569 33.7465 512
0.304663 38.303 1024
0.0728496 42.749 2048
0.028424 50.818 4096
EOD
$t2 << EOD
0.0113696 123.178 256
0.0113696 123.78 512
0.0113696 112.982 1024
0.0113696 97.328 2048
0.0113696 97.0445 4096
EOD
$t3 << EOD
0.0120012 388.489 ""
EOD
$t4 << EOD
4.4553 27.735 256
3.56798 28.9285 512
2.39674 34.425 1024
1.2289 43.5525 2048
0.732974 62.648 4096
EOD
$t5 << EOD
2.66602 227.148 512
2.6251 264.861 2048
EOD
$t6 << EOD
2.26656 33.6 256
1.39301 34.873 512
0.688449 41.332 1024
0.336697 60.696 2048
0.186583 107.583 4096
EOD
$t7 << EOD
2.6357 33.023 256
1.70935 31.5735 512
0.877788 41.934 1024
0.424688 67.5825 2048
0.229412 167.202 4096
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
