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
f(want) = (strcol(1) eq want) ? bin(column(2)) : 1/0
plot for [obj in "bunny dragon"] dir."/stability_distances.csv" every ::1 using (f(obj)):(1.0) smooth frequency with boxes title obj
unset arrow
unset label
set title "Eq. 4: frames of tensors on corresponding vertex pairs, bunny + dragon\n(angle between B_m^T B_s and the ground-truth rotation)"
set xlabel "frame error (deg); last bin: >= 45"
set ylabel "tensor pairs"
v = 1.0
g(dist) = (column(2) == dist) ? v * floor((column(3) < 45 ? column(3) : 45) / v) + v / 2 : 1/0
set boxwidth v
set xrange [0:46]
plot for [dist in "6 2"] dir."/stability_frames.csv" every ::1 using (g(dist + 0)):(1.0) smooth frequency with boxes \
     title "vertices within ".dist." d_{res}"
unset multiplot
