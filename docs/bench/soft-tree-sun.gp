set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/soft-tree-sun.png'
set title 'tree, sun of size 3: frame time against penumbra error (512x384)'
set logscale xy
set xlabel 'vis_mae_penumbra (log)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$t0 << EOD
0.06836 86.253 512
0.06304 104.416 1024
0.06713 205.53 2048
0.07088 134.742 4096
EOD
$t1 << EOD
0.02206 49.394 512
EOD
$t2 << EOD
0.19018 49.559 512
0.21094 24.105 1024
0.22816 26.187 2048
0.2375 30.205 4096
EOD
$t3 << EOD
0.07194 34.367 512
0.12133 43.406 1024
0.17052 31.883 2048
0.20547 43.923 4096
EOD
$t4 << EOD
0.03529 90.915 512
0.03902 82.792 1024
0.04415 136.059 2048
0.0434 102.306 4096
EOD
$t5 << EOD
0.21822 28.794 512
0.23834 28.995 1024
0.24779 48.066 2048
0.24811 34.855 4096
EOD
$t6 << EOD
0.10129 87.511 512
0.10463 45.547 1024
0.10519 112.104 2048
0.1135 63.105 4096
EOD
$t7 << EOD
0.24812 325.243 
EOD
plot $t0 using 1:2 with linespoints pt 7 lc rgb '#1f77b4' title 'SoftShadowMap', $t0 using 1:2:3 with labels offset 1,0.5 tc rgb '#1f77b4' notitle, $t1 using 1:2 with linespoints pt 7 lc rgb '#ff7f0e' title 'hybrid', $t1 using 1:2:3 with labels offset 1,0.5 tc rgb '#ff7f0e' notitle, $t2 using 1:2 with linespoints pt 7 lc rgb '#2ca02c' title 'shadowmap pcf2x2', $t2 using 1:2:3 with labels offset 1,0.5 tc rgb '#2ca02c' notitle, $t3 using 1:2 with linespoints pt 7 lc rgb '#d62728' title 'shadowmap pcf5', $t3 using 1:2:3 with labels offset 1,0.5 tc rgb '#d62728' notitle, $t4 using 1:2 with linespoints pt 7 lc rgb '#9467bd' title 'shadowmap pcss', $t4 using 1:2:3 with labels offset 1,0.5 tc rgb '#9467bd' notitle, $t5 using 1:2 with linespoints pt 7 lc rgb '#8c564b' title 'silhouette', $t5 using 1:2:3 with labels offset 1,0.5 tc rgb '#8c564b' notitle, $t6 using 1:2 with linespoints pt 7 lc rgb '#e377c2' title 'silhouette silhouette', $t6 using 1:2:3 with labels offset 1,0.5 tc rgb '#e377c2' notitle, $t7 using 1:2 with linespoints pt 7 lc rgb '#7f7f7f' title 'volume', $t7 using 1:2:3 with labels offset 1,0.5 tc rgb '#7f7f7f' notitle
