# Wall time and peak memory of pcl_tensor_model against the number of views (scale_benchmark.py),
# with N log N drawn through the point (n0, t0) for comparison.
set terminal pngcairo size 900,600
set output out.'/scale.png'
set xlabel 'views (shuffled)'
set ylabel 'wall time (s)'
set y2label 'peak memory (MB)'
set ytics nomirror
set y2tics
set key top left
set grid
# n0 and t0 (a measured point, given by scale_benchmark.py with -e) anchor the N log N curve.
f(x) = t0 * x * log (x) / (n0 * log (n0))
plot out.'/scale.dat' using 1:2 with linespoints lw 2 title 'wall time', \
     f(x) with lines dt 2 title 'N log N through 104 views', \
     out.'/scale.dat' using 1:3 axes x1y2 with linespoints title 'peak memory'
