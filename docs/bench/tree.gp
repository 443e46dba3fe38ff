set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/tree.png'
set title 'tree: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
4.4553 15.0765
3.56798 15.754
2.39674 17.8385
2.26656 20.514
1.2289 22.0175
0.321507 23.803
0.304663 29.9575
0.185493 30.1525
0.0728496 31.123
0.028424 37.8245
0.0124223 77.4845
0.0120012 257.793
EOD
$t0 << EOD
2.34277 21.056 256
1.35067 27.5315 512
0.647435 26.728 1024
0.321507 23.803 2048
0.185493 30.1525 4096
EOD
$t1 << EOD
1.97473 27.8085 256
1.05569 26.475 512
0.304663 29.9575 1024
0.0728496 31.123 2048
0.028424 37.8245 4096
EOD
$t2 << EOD
0.577112 78.5645 256
0.141278 85.865 512
0.0206337 95.478 1024
0.01537 87.2875 2048
0.0124223 77.4845 4096
EOD
$t3 << EOD
0.0120012 257.793 ""
EOD
$t4 << EOD
4.4553 15.0765 256
3.56798 15.754 512
2.39674 17.8385 1024
1.2289 22.0175 2048
0.732974 36.936 4096
EOD
$t5 << EOD
2.66602 176.262 512
2.6251 214.934 2048
EOD
$t6 << EOD
2.26656 20.514 256
1.39301 22.1055 512
0.688449 26.3835 1024
0.336697 44.023 2048
0.186583 76.073 4096
EOD
$t7 << EOD
2.6357 25.785 256
1.70935 25.422 512
0.877788 31.8635 1024
0.424688 42.08 2048
0.229412 111.968 4096
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
