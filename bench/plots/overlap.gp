# Fig. 18: correct registrations against overlap (Eq. 14), per object and method.
load "bench/plots/common.gp"
set output dir."/overlap.png"
set multiplot layout 1,2
set title "Fig. 18: correct registrations against overlap (every pair)"
set xlabel "overlap (Eq. 14), bins of 0.1"
set ylabel "correct (% of the pairs in the bin)"
set xrange [0:1]
set yrange [0:105]
set key top left noenhanced
files = "tensor fpfh"
pct(lab) = (strcol(1) eq lab) ? column(7) : 1/0
wrong(lab) = (strcol(1) eq lab) ? column(6) : 1/0
plot for [m in files] for [obj in "bunny dragon"] dir."/overlap_bins_".m.".csv" every ::1 \
     using ((column(2) + column(3)) / 2):(pct(obj."_".m)) with linespoints lw 2 pt 7 dt (m eq "fpfh" ? 2 : 1) title obj." ".m
set title "Wrong registrations reported (per overlap bin)"
set ylabel "wrong registrations"
set yrange [0:*]
set key top right
plot for [m in files] for [obj in "bunny dragon"] dir."/overlap_bins_".m.".csv" every ::1 \
     using ((column(2) + column(3)) / 2):(wrong(obj."_".m)) with linespoints lw 2 pt 7 dt (m eq "fpfh" ? 2 : 1) title obj." ".m
unset multiplot
