# Shared look of the experiment plots; every script is run as: gnuplot -e "dir='doc/results'" X.gp
set terminal pngcairo size 1100,450 enhanced font "DejaVu Sans,11"
set datafile separator ","
set datafile missing "nan"
set key top right
set grid ytics
set style fill solid 0.6 border -1
# The rows of a CSV (header dropped) that satisfy an awk condition. Selecting rows with 1/0 in "using"
# would split smoothed histograms and lines at every skipped row.
rows(file, cond) = sprintf("< awk -F, 'NR > 1 && (%s)' %s", cond, file)
