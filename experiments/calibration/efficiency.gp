# efficiency.gp - efficiency T(1)/(n T(n)) against n, one line per data column (hand-over
# costs for the calibration study, mappings for the mapping study).
# Called with: gnuplot -e "data='FILE'; out='PNG'; ttl='TITLE'; ncol=N[; keyt='KEY TITLE']" efficiency.gp
# FILE: whitespace table, header line "n NAME1 NAME2 ...", one row per n.
if (!exists("keyt")) keyt = "hand-over us"
set terminal pngcairo size 720,460 noenhanced
set output out
set title ttl
set logscale x 2
set xlabel "processors n"
set ylabel "efficiency T(1) / (n T(n))"
set yrange [0:1.05]
set grid
set key outside right title keyt
set arrow from graph 0, first 0.85 to graph 1, first 0.85 nohead dt 2 lc rgb "gray40"
plot for [i=2:ncol] data using 1:i with linespoints title columnheader(i)
