set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/soft-default-point.png'
set title 'default, point of size 0.3: frame time against penumbra error (512x384)'
set logscale xy
set xlabel 'vis_mae_penumbra (log)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$t0 << EOD
0.12472 70.715 512
0.1205 106.993 1024
0.12038 39.265 2048
0.12037 85.387 4096
EOD
$t1 << EOD
0.01095 52.148 512
EOD
$t2 << EOD
0.18981 27.998 512
0.20527 21.102 1024
0.22158 36.151 2048
0.22997 28.011 4096
EOD
$t3 << EOD
0.08992 52.011 512
0.12566 20.003 1024
0.17505 44.257 2048
0.20003 63.708 4096
EOD
$t4 << EOD
0.05768 135.968 512
0.03718 51.125 1024
0.04115 105.149 2048
0.04201 110.722 4096
EOD
$t5 << EOD
0.2362 31.99 512
0.2362 40.672 1024
0.23611 32.667 2048
0.23611 47.908 4096
EOD
$t6 << EOD
0.03227 43.99 512
0.03234 72.773 1024
0.03299 26.061 2048
0.05681 50.524 4096
EOD
$t7 << EOD
0.23611 41.349 
EOD
plot $t0 using 1:2 with linespoints pt 7 lc rgb '#1f77b4' title 'SoftShadowMap', $t0 using 1:2:3 with labels offset 1,0.5 tc rgb '#1f77b4' notitle, $t1 using 1:2 with linespoints pt 7 lc rgb '#ff7f0e' title 'hybrid', $t1 using 1:2:3 with labels offset 1,0.5 tc rgb '#ff7f0e' notitle, $t2 using 1:2 with linespoints pt 7 lc rgb '#2ca02c' title 'shadowmap pcf2x2', $t2 using 1:2:3 with labels offset 1,0.5 tc rgb '#2ca02c' notitle, $t3 using 1:2 with linespoints pt 7 lc rgb '#d62728' title 'shadowmap pcf5', $t3 using 1:2:3 with labels offset 1,0.5 tc rgb '#d62728' notitle, $t4 using 1:2 with linespoints pt 7 lc rgb '#9467bd' title 'shadowmap pcss', $t4 using 1:2:3 with labels offset 1,0.5 tc rgb '#9467bd' notitle, $t5 using 1:2 with linespoints pt 7 lc rgb '#8c564b' title 'silhouette', $t5 using 1:2:3 with labels offset 1,0.5 tc rgb '#8c564b' notitle, $t6 using 1:2 with linespoints pt 7 lc rgb '#e377c2' title 'silhouette silhouette', $t6 using 1:2:3 with labels offset 1,0.5 tc rgb '#e377c2' notitle, $t7 using 1:2 with linespoints pt 7 lc rgb '#7f7f7f' title 'volume', $t7 using 1:2:3 with labels offset 1,0.5 tc rgb '#7f7f7f' notitle
