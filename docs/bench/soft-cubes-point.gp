set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/soft-cubes-point.png'
set title 'cubes, point of size 0.3: frame time against penumbra error (512x384)'
set logscale xy
set xlabel 'vis_mae_penumbra (log)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$t0 << EOD
0.10816 373.186 1024
0.11013 504.092 2048
EOD
$t1 << EOD
0.01197 72.111 512
EOD
$t2 << EOD
0.21377 132.4 1024
0.22373 144.609 2048
EOD
$t3 << EOD
0.13857 219.849 1024
0.17044 236.011 2048
EOD
$t4 << EOD
0.0589 606.388 1024
0.05503 751.837 2048
EOD
$t5 << EOD
0.24297 155.06 1024
0.2425 282.462 2048
EOD
$t6 << EOD
0.08313 301.085 1024
0.08101 424.871 2048
EOD
$t7 << EOD
0.24248 376.607 
EOD
plot $t0 using 1:2 with linespoints pt 7 lc rgb '#1f77b4' title 'SoftShadowMap', $t0 using 1:2:3 with labels offset 1,0.5 tc rgb '#1f77b4' notitle, $t1 using 1:2 with linespoints pt 7 lc rgb '#ff7f0e' title 'hybrid', $t1 using 1:2:3 with labels offset 1,0.5 tc rgb '#ff7f0e' notitle, $t2 using 1:2 with linespoints pt 7 lc rgb '#2ca02c' title 'shadowmap pcf2x2', $t2 using 1:2:3 with labels offset 1,0.5 tc rgb '#2ca02c' notitle, $t3 using 1:2 with linespoints pt 7 lc rgb '#d62728' title 'shadowmap pcf5', $t3 using 1:2:3 with labels offset 1,0.5 tc rgb '#d62728' notitle, $t4 using 1:2 with linespoints pt 7 lc rgb '#9467bd' title 'shadowmap pcss', $t4 using 1:2:3 with labels offset 1,0.5 tc rgb '#9467bd' notitle, $t5 using 1:2 with linespoints pt 7 lc rgb '#8c564b' title 'silhouette', $t5 using 1:2:3 with labels offset 1,0.5 tc rgb '#8c564b' notitle, $t6 using 1:2 with linespoints pt 7 lc rgb '#e377c2' title 'silhouette silhouette', $t6 using 1:2:3 with labels offset 1,0.5 tc rgb '#e377c2' notitle, $t7 using 1:2 with linespoints pt 7 lc rgb '#7f7f7f' title 'volume', $t7 using 1:2:3 with labels offset 1,0.5 tc rgb '#7f7f7f' notitle
