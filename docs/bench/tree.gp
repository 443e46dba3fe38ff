set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
4.4553 16.703
2.26656 18.308
1.35067 20.8515
0.688449 23.4255
0.321507 24.2025
0.185493 28.9125
0.0728496 40.771
0.028424 54.5445
0.0113696 73.3675
EOD
$t0 << EOD
2.34277 22.1215 256
1.35067 20.8515 512
0.647435 24.266 1024
0.321507 24.2025 2048
0.185493 28.9125 4096
EOD
$t1 << EOD
1.97473 34.5465 256
1.05569 35.5965 512
0.304663 36.3835 1024
0.0728496 40.771 2048
0.028424 54.5445 4096
EOD
$t2 << EOD
0.0113696 111.355 256
0.0113696 104.653 512
0.0113696 97.4795 1024
0.0113696 75.1965 2048
0.0113696 73.3675 4096
EOD
$t3 << EOD
0.0120012 277.738 ""
EOD
$t4 << EOD
4.4553 16.703 256
3.56798 19.203 512
2.39674 24.079 1024
1.2289 38.1695 2048
0.732974 42.467 4096
EOD
$t5 << EOD
2.66602 205.484 512
2.6251 219.459 2048
EOD
$t6 << EOD
2.26656 18.308 256
1.39301 22.379 512
0.688449 23.4255 1024
0.336697 38.5035 2048
0.186583 74.0915 4096
EOD
$t7 << EOD
2.6357 21.7335 256
1.70935 20.869 512
0.877788 23.8525 1024
0.424688 41.8155 2048
0.229412 146.898 4096
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
