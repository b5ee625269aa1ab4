# Fig. 21: ground-truth displacement of the best matches, tensors against spin images.
load "bench/plots/common.gp"
set output dir."/discrimination.png"
set multiplot layout 1,2
set xlabel "ground-truth displacement (bins); last bin: >= 40"
set ylabel "matches"
w = 1.0
set boxwidth w
set xrange [0:41]
set arrow from 5, graph 0 to 5, graph 1 nohead dt 2 lw 2 lc rgb "#c03020" front
set label "5 bins (paper: 2 cm)" at 5.5, graph 0.9 tc rgb "#c03020" front
bin(x) = w * floor((x < 40 ? x : 40) / w) + w / 2
set title "Fig. 21a: spin images (PCL, width 8), best 200 matches per pair"
plot rows(dir."/discrimination.csv", "$4 == \"spin\"") using (bin(column(6))):(1.0) smooth frequency with boxes lc rgb "#808080" title "spin images"
set title "Fig. 21b: tensors (15^3), best 200 matches per pair"
plot rows(dir."/discrimination.csv", "$4 == \"tensor\"") using (bin(column(6))):(1.0) smooth frequency with boxes lc rgb "#3060a0" title "tensors"
unset multiplot
