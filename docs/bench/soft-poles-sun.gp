set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/soft-poles-sun.png'
set title 'poles, sun of size 3: frame time against penumbra error (512x384)'
set logscale xy
set xlabel 'vis_mae_penumbra (log)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$t0 << EOD
0.11932 82.529 512
0.11457 95.464 1024
0.11432 108.565 2048
0.11519 107.403 4096
EOD
$t1 << EOD
0.01227 33.624 512
EOD
$t2 << EOD
0.22844 20.046 512
0.24486 20.175 1024
0.26172 21.024 2048
0.27126 23.793 4096
EOD
$t3 << EOD
0.11131 35.772 512
0.12713 22.553 1024
0.18791 26.857 2048
0.23011 31.024 4096
EOD
$t4 << EOD
0.09514 72.049 512
0.07312 62.42 1024
0.07198 69.5 2048
0.0494 80.112 4096
EOD
$t5 << EOD
0.28373 17.158 512
0.28373 18.032 1024
0.28355 20.771 2048
0.28356 26.857 4096
EOD
$t6 << EOD
0.03113 25.245 512
0.02908 27.804 1024
0.0292 44.627 2048
0.03409 41.588 4096
EOD
$t7 << EOD
0.28356 29.453 
EOD
plot $t0 using 1:2 with linespoints pt 7 lc rgb '#1f77b4' title 'SoftShadowMap', $t0 using 1:2:3 with labels offset 1,0.5 tc rgb '#1f77b4' notitle, $t1 using 1:2 with linespoints pt 7 lc rgb '#ff7f0e' title 'hybrid', $t1 using 1:2:3 with labels offset 1,0.5 tc rgb '#ff7f0e' notitle, $t2 using 1:2 with linespoints pt 7 lc rgb '#2ca02c' title 'shadowmap pcf2x2', $t2 using 1:2:3 with labels offset 1,0.5 tc rgb '#2ca02c' notitle, $t3 using 1:2 with linespoints pt 7 lc rgb '#d62728' title 'shadowmap pcf5', $t3 using 1:2:3 with labels offset 1,0.5 tc rgb '#d62728' notitle, $t4 using 1:2 with linespoints pt 7 lc rgb '#9467bd' title 'shadowmap pcss', $t4 using 1:2:3 with labels offset 1,0.5 tc rgb '#9467bd' notitle, $t5 using 1:2 with linespoints pt 7 lc rgb '#8c564b' title 'silhouette', $t5 using 1:2:3 with labels offset 1,0.5 tc rgb '#8c564b' notitle, $t6 using 1:2 with linespoints pt 7 lc rgb '#e377c2' title 'silhouette silhouette', $t6 using 1:2:3 with labels offset 1,0.5 tc rgb '#e377c2' notitle, $t7 using 1:2 with linespoints pt 7 lc rgb '#7f7f7f' title 'volume', $t7 using 1:2:3 with labels offset 1,0.5 tc rgb '#7f7f7f' notitle
