set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
4.4553 16.0405
2.34277 18.5185
1.35067 19.296
0.647435 21.9185
0.321507 24.3645
0.185493 27.8075
0.0728496 29.5845
0.028424 38.205
0.00252658 50.1045
0.00231603 53.4465
EOD
$t0 << EOD
2.34277 18.5185 256
1.35067 19.296 512
0.647435 21.9185 1024
0.321507 24.3645 2048
0.185493 27.8075 4096
EOD
$t1 << EOD
1.97473 29.4285 256
1.05569 30.2285 512
0.304663 31.1955 1024
0.0728496 29.5845 2048
0.028424 38.205 4096
EOD
$t2 << EOD
0.00252658 64.542 256
0.00252658 68.2035 512
0.00231603 53.4465 1024
0.00252658 50.1045 2048
0.00273712 55.6485 4096
EOD
$t3 << EOD
0.0120012 282.969 ""
EOD
$t4 << EOD
4.4553 16.0405 256
3.56798 18.95 512
2.39674 19.0985 1024
1.2289 29.024 2048
0.732974 48.7795 4096
EOD
$t5 << EOD
2.66602 174.832 512
2.6251 176.008 2048
EOD
$t6 << EOD
2.26656 21.3 256
1.39301 20.046 512
0.688449 23.468 1024
0.336697 32.362 2048
0.186583 60.9325 4096
EOD
$t7 << EOD
2.6357 19.501 256
1.70935 19.495 512
0.877788 27.39 1024
0.424688 34.701 2048
0.229412 95.615 4096
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
