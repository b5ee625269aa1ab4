# Fig. 18: correct registrations against overlap (Eq. 14), per object and method.
load "bench/plots/common.gp"
set output dir."/overlap.png"
set multiplot layout 1,2
set title "Fig. 18: correct registrations against overlap"
set xlabel "overlap (Eq. 14), bins of 0.1"
set ylabel "correct (% of the pairs in the bin)"
set xrange [0:1]
set yrange [0:105]
set key bottom right noenhanced
bins(m, obj) = rows(dir."/overlap_bins_".m.".csv", sprintf("$1 == \"%s_%s\" && $4 > 0", obj, m))
plot for [obj in "bunny dragon"] bins("tensor", obj) using (($2 + $3) / 2):7 with linespoints lw 2 pt 7 title "tensors, ".obj, \
     for [obj in "bunny dragon"] bins("fpfh", obj) using (($2 + $3) / 2):7 with linespoints lw 2 pt 5 dt 2 title "FPFH, ".obj
set title "Wrong registrations reported (per overlap bin)"
set ylabel "wrong registrations"
set yrange [0:*]
set key top right
plot for [obj in "bunny dragon"] bins("tensor", obj) using (($2 + $3) / 2):6 with linespoints lw 2 pt 7 title "tensors, ".obj, \
     for [obj in "bunny dragon"] bins("fpfh", obj) using (($2 + $3) / 2):6 with linespoints lw 2 pt 5 dt 2 title "FPFH, ".obj
unset multiplot
