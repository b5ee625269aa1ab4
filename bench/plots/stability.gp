# Section 3, Figs. 4(d) and 5: nearest-vertex distances after reduction, and Eq. 4's frame residuals.
load "bench/plots/common.gp"
set output dir."/stability.png"
set multiplot layout 1,2
set style fill transparent solid 0.45 border -1
set title "Figs. 4d/5: reduced scene vertex to nearest reduced model vertex\n(400 faces, pairs with overlap >= 0.5)"
set xlabel "distance (d_{res} of the fine meshes); last bin: >= 40"
set ylabel "vertices"
set yrange [0:*]
w = 1.0
bin(x) = w * floor((x < 40 ? x : 40) / w) + w / 2
set boxwidth w
set xrange [0:41]
set arrow from 2, graph 0 to 2, graph 1 nohead dt 2 lc rgb "black"
set label "2 d_{res}" at 2.5, graph 0.95
plot for [obj in "bunny dragon"] rows(dir."/stability_distances.csv", sprintf("$1 == \"%s\"", obj)) using (bin(column(2))):(1.0) \
     smooth frequency with boxes title obj
unset arrow
unset label
frames(dist) = rows(dir."/stability_frames.csv", sprintf("$2 == %d", dist))
set autoscale
stats frames(6) using 3 name "S6" nooutput
stats frames(2) using 3 name "S2" nooutput
set title "Eq. 4: tensors on corresponding vertex pairs (bunny + dragon)\nangle between B_m^T B_s and the ground-truth rotation"
set xlabel "frame error (deg)"
set ylabel "fraction of the tensor pairs with at most this error"
set xrange [0:180]
set yrange [0:1]
set key bottom right
plot frames(6) using 3:(1.0 / S6_records) smooth cumulative with lines lw 2 title sprintf("vertices within 6 d_{res} (%d tensor pairs)", S6_records), \
     frames(2) using 3:(1.0 / S2_records) smooth cumulative with lines lw 2 title sprintf("vertices within 2 d_{res} (%d tensor pairs)", S2_records)
unset multiplot
