# Section 7.5: correct registrations against noise along the viewing direction.
load "bench/plots/common.gp"
set terminal pngcairo size 650,450 enhanced font "DejaVu Sans,11"
set output dir."/noise.png"
set title "Sec. 7.5: synthetic bunny, adjacent pairs, Gaussian noise"
set xlabel "noise {/Symbol s} along the viewing direction (d_{res})"
set ylabel "correct (% of pairs)"
set xrange [-0.3:4.3]
set yrange [0:105]
set key bottom left
plot dir."/noise.csv" every ::1 using 1:5 with linespoints lw 2 pt 7 title "ours", \
     "-" using 1:2 with points pt 6 ps 2 lc rgb "#c03020" title "paper: close to 100% up to 3 d_{res}"
1,100
2,100
3,100
e
