set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/soft-poles-point.png'
set title 'poles, point of size 0.3: frame time against penumbra error (512x384)'
set logscale xy
set xlabel 'vis_mae_penumbra (log)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$t0 << EOD
0.12866 81.092 512
0.12366 85.832 1024
0.12302 88.042 2048
0.12313 104.885 4096
EOD
$t1 << EOD
0.0178 67.975 512
EOD
$t2 << EOD
0.21195 25.776 512
0.23149 25.13 1024
0.24229 31.817 2048
0.24799 32.642 4096
EOD
$t3 << EOD
0.09817 48.178 512
0.15636 48.83 1024
0.20149 56.315 2048
0.22678 64.688 4096
EOD
$t4 << EOD
0.04736 134.958 512
0.04485 133.594 1024
0.04251 133.719 2048
0.04074 152.077 4096
EOD
$t5 << EOD
0.25483 31.922 512
0.25433 36.922 1024
0.25438 35.514 2048
0.25429 40.053 4096
EOD
$t6 << EOD
0.03884 75.236 512
0.03923 60.379 1024
0.04089 60.578 2048
0.07451 67.876 4096
EOD
$t7 << EOD
0.25427 38.007 
EOD
plot $t0 using 1:2 with linespoints pt 7 lc rgb '#1f77b4' title 'SoftShadowMap', $t0 using 1:2:3 with labels offset 1,0.5 tc rgb '#1f77b4' notitle, $t1 using 1:2 with linespoints pt 7 lc rgb '#ff7f0e' title 'hybrid', $t1 using 1:2:3 with labels offset 1,0.5 tc rgb '#ff7f0e' notitle, $t2 using 1:2 with linespoints pt 7 lc rgb '#2ca02c' title 'shadowmap pcf2x2', $t2 using 1:2:3 with labels offset 1,0.5 tc rgb '#2ca02c' notitle, $t3 using 1:2 with linespoints pt 7 lc rgb '#d62728' title 'shadowmap pcf5', $t3 using 1:2:3 with labels offset 1,0.5 tc rgb '#d62728' notitle, $t4 using 1:2 with linespoints pt 7 lc rgb '#9467bd' title 'shadowmap pcss', $t4 using 1:2:3 with labels offset 1,0.5 tc rgb '#9467bd' notitle, $t5 using 1:2 with linespoints pt 7 lc rgb '#8c564b' title 'silhouette', $t5 using 1:2:3 with labels offset 1,0.5 tc rgb '#8c564b' notitle, $t6 using 1:2 with linespoints pt 7 lc rgb '#e377c2' title 'silhouette silhouette', $t6 using 1:2:3 with labels offset 1,0.5 tc rgb '#e377c2' notitle, $t7 using 1:2 with linespoints pt 7 lc rgb '#7f7f7f' title 'volume', $t7 using 1:2:3 with labels offset 1,0.5 tc rgb '#7f7f7f' notitle
