set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
4.4553 17.213
2.26656 19.778
1.70935 23.4465
1.35067 23.9455
0.688449 25.6295
0.647435 26.5665
0.321507 28.5955
0.304663 29.4335
0.0728496 32.352
0.028424 37.3755
0.0113696 59.062
EOD
$t0 << EOD
2.34277 22.3275 256
1.35067 23.9455 512
0.647435 26.5665 1024
0.321507 28.5955 2048
0.185493 36.9495 4096
EOD
$t1 << EOD
1.97473 31.737 256
1.05569 32.068 512
0.304663 29.4335 1024
0.0728496 32.352 2048
0.028424 37.3755 4096
EOD
$t2 << EOD
0.0113696 66.7575 256
0.0113696 61.207 512
0.0113696 59.062 1024
0.0113696 68.006 2048
0.0113696 66.17 4096
EOD
$t3 << EOD
0.0120012 327.966 ""
EOD
$t4 << EOD
4.4553 17.213 256
3.56798 24.863 512
2.39674 20.794 1024
1.2289 35.8545 2048
0.732974 45.6185 4096
EOD
$t5 << EOD
2.66602 203.766 512
2.6251 216.509 2048
EOD
$t6 << EOD
2.26656 19.778 256
1.39301 25.269 512
0.688449 25.6295 1024
0.336697 39.4585 2048
0.186583 77.646 4096
EOD
$t7 << EOD
2.6357 23.477 256
1.70935 23.4465 512
0.877788 36.094 1024
0.424688 58.1315 2048
0.229412 109.199 4096
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
