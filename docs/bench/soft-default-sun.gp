set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/soft-default-sun.png'
set title 'default, sun of size 3: frame time against penumbra error (512x384)'
set logscale xy
set xlabel 'vis_mae_penumbra (log)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$t0 << EOD
0.08843 73.008 512
0.08549 153.072 1024
0.084 169.762 2048
0.08478 112.88 4096
EOD
$t1 << EOD
0.0108 25.968 512
EOD
$t2 << EOD
0.17352 19.99 512
0.20209 32.027 1024
0.21747 32.781 2048
0.22616 27.999 4096
EOD
$t3 << EOD
0.0816 27.99 512
0.10145 40.881 1024
0.15566 64.954 2048
0.19471 40.004 4096
EOD
$t4 << EOD
0.05046 63.97 512
0.04386 129.514 1024
0.04293 127.281 2048
0.03898 82.151 4096
EOD
$t5 << EOD
0.23672 23.31 512
0.2368 44.174 1024
0.23666 40.26 2048
0.23666 28.014 4096
EOD
$t6 << EOD
0.00785 35.963 512
0.00747 69.95 1024
0.00743 64.12 2048
0.02396 52.002 4096
EOD
$t7 << EOD
0.23666 71.793 
EOD
plot $t0 using 1:2 with linespoints pt 7 lc rgb '#1f77b4' title 'SoftShadowMap', $t0 using 1:2:3 with labels offset 1,0.5 tc rgb '#1f77b4' notitle, $t1 using 1:2 with linespoints pt 7 lc rgb '#ff7f0e' title 'hybrid', $t1 using 1:2:3 with labels offset 1,0.5 tc rgb '#ff7f0e' notitle, $t2 using 1:2 with linespoints pt 7 lc rgb '#2ca02c' title 'shadowmap pcf2x2', $t2 using 1:2:3 with labels offset 1,0.5 tc rgb '#2ca02c' notitle, $t3 using 1:2 with linespoints pt 7 lc rgb '#d62728' title 'shadowmap pcf5', $t3 using 1:2:3 with labels offset 1,0.5 tc rgb '#d62728' notitle, $t4 using 1:2 with linespoints pt 7 lc rgb '#9467bd' title 'shadowmap pcss', $t4 using 1:2:3 with labels offset 1,0.5 tc rgb '#9467bd' notitle, $t5 using 1:2 with linespoints pt 7 lc rgb '#8c564b' title 'silhouette', $t5 using 1:2:3 with labels offset 1,0.5 tc rgb '#8c564b' notitle, $t6 using 1:2 with linespoints pt 7 lc rgb '#e377c2' title 'silhouette silhouette', $t6 using 1:2:3 with labels offset 1,0.5 tc rgb '#e377c2' notitle, $t7 using 1:2 with linespoints pt 7 lc rgb '#7f7f7f' title 'volume', $t7 using 1:2:3 with labels offset 1,0.5 tc rgb '#7f7f7f' notitle
