set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/soft-bunny-point.png'
set title 'bunny, point of size 0.3: frame time against penumbra error (512x384)'
set logscale xy
set xlabel 'vis_mae_penumbra (log)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$t0 << EOD
0.11731 196.452 1024
0.11987 219.608 2048
EOD
$t1 << EOD
0.01163 274.812 512
EOD
$t2 << EOD
0.21644 51.5 1024
0.21766 174.527 2048
EOD
$t3 << EOD
0.17906 185.672 1024
0.1928 133.844 2048
EOD
$t4 << EOD
0.05181 168.366 1024
0.04999 322.512 2048
EOD
$t5 << EOD
0.24359 134.363 1024
0.23971 164.257 2048
EOD
$t6 << EOD
0.06058 188.496 1024
0.07456 193.774 2048
EOD
$t7 << EOD
0.23613 110.752 
EOD
plot $t0 using 1:2 with linespoints pt 7 lc rgb '#1f77b4' title 'SoftShadowMap', $t0 using 1:2:3 with labels offset 1,0.5 tc rgb '#1f77b4' notitle, $t1 using 1:2 with linespoints pt 7 lc rgb '#ff7f0e' title 'hybrid', $t1 using 1:2:3 with labels offset 1,0.5 tc rgb '#ff7f0e' notitle, $t2 using 1:2 with linespoints pt 7 lc rgb '#2ca02c' title 'shadowmap pcf2x2', $t2 using 1:2:3 with labels offset 1,0.5 tc rgb '#2ca02c' notitle, $t3 using 1:2 with linespoints pt 7 lc rgb '#d62728' title 'shadowmap pcf5', $t3 using 1:2:3 with labels offset 1,0.5 tc rgb '#d62728' notitle, $t4 using 1:2 with linespoints pt 7 lc rgb '#9467bd' title 'shadowmap pcss', $t4 using 1:2:3 with labels offset 1,0.5 tc rgb '#9467bd' notitle, $t5 using 1:2 with linespoints pt 7 lc rgb '#8c564b' title 'silhouette', $t5 using 1:2:3 with labels offset 1,0.5 tc rgb '#8c564b' notitle, $t6 using 1:2 with linespoints pt 7 lc rgb '#e377c2' title 'silhouette silhouette', $t6 using 1:2:3 with labels offset 1,0.5 tc rgb '#e377c2' notitle, $t7 using 1:2 with linespoints pt 7 lc rgb '#7f7f7f' title 'volume', $t7 using 1:2:3 with labels offset 1,0.5 tc rgb '#7f7f7f' notitle
