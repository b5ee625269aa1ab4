# Figs. 15-16 and 20: correct registrations of the overlapping real pairs against faces and tensors per view.
load "bench/plots/common.gp"
set output dir."/resolution.png"
set multiplot layout 1,2
set ylabel "correct (% of pairs with overlap >= 0.5)"
set yrange [0:105]
set key bottom right noenhanced
sel(sweep, method, obj) = rows(dir."/resolution.csv", sprintf("$1 == \"%s\" && $3 == \"%s\" && $4 == \"%s\"", sweep, method, obj))
set title "Figs. 16 and 20: faces per view (M'_i)"
set xlabel "faces per view"
set xrange [0:1100]
plot for [obj in "bunny dragon all"] sel("faces", "tensor", obj) using 2:(100.0 * column(6) / column(5)) with linespoints lw 2 pt 7 title "tensors, ".obj, \
     for [obj in "bunny dragon all"] sel("faces", "spin", obj) using 2:(100.0 * column(6) / column(5)) with linespoints lw 2 pt 5 dt 2 title "spin images, ".obj, \
     "-" using 1:2 with points pt 6 ps 2 lc rgb "#c03020" title "paper, tensors (Figs. 16, 20)", \
     "-" using 1:2 with points pt 4 ps 2 lc rgb "#c03020" title "paper, spin images (Fig. 20)"
100,50
200,84
600,100
e
200,30
600,61
e
set title "Fig. 16: tensors per view (1000 faces)"
set xlabel "tensors per view"
set xrange [0:800]
plot for [obj in "bunny dragon all"] sel("tensors", "tensor", obj) using 2:(100.0 * column(6) / column(5)) with linespoints lw 2 pt 7 title obj, \
     "-" using 1:2 with points pt 6 ps 2 lc rgb "#c03020" title "paper: ~90% at 450"
450,90
e
unset multiplot
