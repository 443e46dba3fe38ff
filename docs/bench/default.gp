set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.893912 9.6915
0.508652 10.568
0.147197 11.7835
0.0789634 11.8245
0.001 12.6645
EOD
$t0 << EOD
0.142379 11.8785 256
0.0698492 12.715 512
0.0338358 12.8275 1024
0.018258 13.6145 2048
0.00954774 17.6675 4096
EOD
$t1 << EOD
0.0118928 22.079 256
0.00234506 23.308 512
0.00117253 24.2815 1024
0.001 24.567 2048
0.001 32.321 4096
EOD
$t2 << EOD
0.00167504 52.5125 256
0.001 42.3615 512
0.001 42.6725 1024
0.001 45.785 2048
0.001 43.1555 4096
EOD
$t3 << EOD
0.001 12.6645 ""
EOD
$t4 << EOD
0.893912 9.6915 256
0.508652 10.568 512
0.269079 14.4765 1024
0.125738 17.6675 2048
0.0734309 29.931 4096
EOD
$t5 << EOD
0.0746045 249.001 512
0.0526423 280.149 2048
EOD
$t6 << EOD
0.118697 15.863 256
0.0591806 16.9055 512
0.0320212 25.2295 1024
0.0147532 30.623 2048
0.00771192 60.516 4096
EOD
$t7 << EOD
0.147197 11.7835 256
0.0789634 11.8245 512
0.0404038 13.664 1024
0.0160944 27.5115 2048
0.0107296 84.7065 4096
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
