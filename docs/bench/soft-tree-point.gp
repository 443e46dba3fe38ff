set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/soft-tree-point.png'
set title 'tree, point of size 0.3: frame time against penumbra error (512x384)'
set logscale xy
set xlabel 'vis_mae_penumbra (log)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$t0 << EOD
0.06283 125.617 512
0.05711 227.994 1024
0.06081 220.287 2048
0.06403 141.109 4096
EOD
$t1 << EOD
0.01735 98.469 512
EOD
$t2 << EOD
0.23843 53.965 512
0.25568 251.967 1024
0.26494 133.982 2048
0.26937 57.779 4096
EOD
$t3 << EOD
0.14022 78.575 512
0.19921 176.375 1024
0.23508 191.255 2048
0.25422 99.679 4096
EOD
$t4 << EOD
0.04927 156.753 512
0.04995 340.027 1024
0.04645 340.034 2048
0.06288 198.623 4096
EOD
$t5 << EOD
0.27316 48.874 512
0.27438 128.388 1024
0.27433 116.026 2048
0.27435 49.612 4096
EOD
$t6 << EOD
0.07013 78.413 512
0.07324 79.948 1024
0.08564 85.805 2048
0.13297 100.109 4096
EOD
$t7 << EOD
0.27436 1203.211 
EOD
plot $t0 using 1:2 with linespoints pt 7 lc rgb '#1f77b4' title 'SoftShadowMap', $t0 using 1:2:3 with labels offset 1,0.5 tc rgb '#1f77b4' notitle, $t1 using 1:2 with linespoints pt 7 lc rgb '#ff7f0e' title 'hybrid', $t1 using 1:2:3 with labels offset 1,0.5 tc rgb '#ff7f0e' notitle, $t2 using 1:2 with linespoints pt 7 lc rgb '#2ca02c' title 'shadowmap pcf2x2', $t2 using 1:2:3 with labels offset 1,0.5 tc rgb '#2ca02c' notitle, $t3 using 1:2 with linespoints pt 7 lc rgb '#d62728' title 'shadowmap pcf5', $t3 using 1:2:3 with labels offset 1,0.5 tc rgb '#d62728' notitle, $t4 using 1:2 with linespoints pt 7 lc rgb '#9467bd' title 'shadowmap pcss', $t4 using 1:2:3 with labels offset 1,0.5 tc rgb '#9467bd' notitle, $t5 using 1:2 with linespoints pt 7 lc rgb '#8c564b' title 'silhouette', $t5 using 1:2:3 with labels offset 1,0.5 tc rgb '#8c564b' notitle, $t6 using 1:2 with linespoints pt 7 lc rgb '#e377c2' title 'silhouette silhouette', $t6 using 1:2:3 with labels offset 1,0.5 tc rgb '#e377c2' notitle, $t7 using 1:2 with linespoints pt 7 lc rgb '#7f7f7f' title 'volume', $t7 using 1:2:3 with labels offset 1,0.5 tc rgb '#7f7f7f' notitle
