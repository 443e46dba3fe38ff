set terminal pngcairo size 900,600 noenhanced font ',10'
set output 'docs/bench/default.png'
set title 'default: frame time against error (1024x768)'
set logscale xy
set xlabel 'wrong pixels, % of geometry pixels (log; 0 drawn at 0.001)'
set ylabel 'frame time, ms (median, log)'
set grid
set key outside right top
$front << EOD
0.147197 7.009
0.0789634 7.844
0.0404038 11.1965
0.0320212 11.9175
0.001 13.666
EOD
$t0 << EOD
0.142379 11.801 256
0.0698492 11.668 512
0.0338358 13.867 1024
0.018258 16.73 2048
0.00954774 19.752 4096
EOD
$t1 << EOD
0.0118928 16.668 256
0.00234506 19.833 512
0.00117253 20.9955 1024
0.001 21.923 2048
0.001 28.237 4096
EOD
$t2 << EOD
0.001 25.0125 256
0.001 20.4275 512
0.001 22.1745 1024
0.001 24.71 2048
0.001 31.959 4096
EOD
$t3 << EOD
0.001 13.666 ""
EOD
$t4 << EOD
0.893912 13.3145 256
0.508652 10.9985 512
0.269079 12.4045 1024
0.125738 16.946 2048
0.0734309 32.13 4096
EOD
$t5 << EOD
0.0746045 168.561 512
0.0526423 195.962 2048
EOD
$t6 << EOD
0.118697 12.456 256
0.0591806 13.2285 512
0.0320212 11.9175 1024
0.0147532 19.395 2048
0.00771192 43.9085 4096
EOD
$t7 << EOD
0.147197 7.009 256
0.0789634 7.844 512
0.0404038 11.1965 1024
0.0160944 19.524 2048
0.0107296 64.2595 4096
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
