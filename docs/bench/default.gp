set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.893912 10.029
0.147197 11.3035
0.001 11.427
EOD
$t0 << EOD
0.142379 13.8755 256
0.0698492 11.5105 512
0.0338358 12.4295 1024
0.018258 14.7395 2048
0.00954774 20.9845 4096
EOD
$t1 << EOD
0.0118928 23.354 256
0.00234506 24.933 512
0.00117253 28.555 1024
0.001 35.564 2048
0.001 56.239 4096
EOD
$t2 << EOD
0.001 34.072 256
0.001 34.0535 512
0.001 29.5555 1024
0.001 34.9445 2048
0.001 46.875 4096
EOD
$t3 << EOD
0.001 11.427 ""
EOD
$t4 << EOD
0.893912 10.029 256
0.508652 12.0445 512
0.269079 12.474 1024
0.125738 26.207 2048
0.0734309 42.312 4096
EOD
$t5 << EOD
0.0746045 173.938 512
0.0526423 205.154 2048
EOD
$t6 << EOD
0.118697 12.054 256
0.0591806 15.287 512
0.0320212 21.8215 1024
0.0147532 31.645 2048
0.00771192 70.466 4096
EOD
$t7 << EOD
0.147197 11.3035 256
0.0789634 14.04 512
0.0404038 17.08 1024
0.0160944 31.088 2048
0.0107296 87.0285 4096
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
