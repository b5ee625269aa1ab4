# Fig. 13: histograms of the rotation and translation errors of the correct synthetic pairs.
load "bench/plots/common.gp"
set output dir."/accuracy.png"
set multiplot layout 1,2
set style fill transparent solid 0.45 border -1
set ylabel "pairs"
set title "Fig. 13: rotation error (Eq. 11), correct adjacent synthetic pairs"
set xlabel "rotation error (deg); last bin: >= 0.3"
w = 0.01
bin(x) = w * floor((x < 0.3 ? x : 0.3) / w) + w / 2
set boxwidth w
set xrange [0:0.32]
plot for [obj in "bunny dragon example"] rows(dir."/accuracy_".obj.".csv", "$6 == 1") \
     using (bin(column(8))):(1.0) smooth frequency with boxes title obj
set title "Fig. 13: translation error (Eq. 12), correct adjacent synthetic pairs"
set xlabel "translation error (d_{res}); last bin: >= 1"
v = 0.04
tbin(x) = v * floor((x < 1.0 ? x : 1.0) / v) + v / 2
set boxwidth v
set xrange [0:1.06]
plot for [obj in "bunny dragon example"] rows(dir."/accuracy_".obj.".csv", "$6 == 1") \
     using (tbin(column(9))):(1.0) smooth frequency with boxes title obj
unset multiplot
