# Fig. 17: (a) tensors of M'_s matched before success, (b) PDF of theta_d with the paper's Gamma fit.
load "bench/plots/common.gp"
set output dir."/efficiency.png"
set multiplot layout 1,2
set title "Fig. 17a: tensors of M'_s matched before success\n(scene order, correct pairs with overlap >= 0.5)"
set xlabel "tensors of M'_s matched"
set ylabel "pairs"
w = 25
bin(x) = w * floor(x / w) + w / 2.0
set boxwidth w * 0.9
set xrange [0:*]
set yrange [0:*]
plot rows(dir."/efficiency.csv", "$6 == 1") using (bin(column(7))):(1.0) smooth frequency with boxes lc rgb "#3060a0" title "ours (bunny + dragon)"
set title "Fig. 17b: PDF of {/Symbol q}_d of every tensor (5 deg bins)"
set xlabel "{/Symbol q}_d (deg)"
set ylabel "probability density (1/deg)"
set xrange [0:180]
gamma_pdf(x) = x <= 0 ? 0 : x**1.5 * exp(-x / 20.0) / (gamma(2.5) * 20.0**2.5)
set boxwidth 4.5
plot dir."/theta_pdf.csv" every ::1 using (column(1) + 2.5):(column(2) / 5.0) with boxes lc rgb "#3060a0" title "ours", \
     gamma_pdf(x) with lines lw 2 lc rgb "#c03020" title "paper: Gamma({/Symbol a}=2.5, {/Symbol b}=20)"
unset multiplot
