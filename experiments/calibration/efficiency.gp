# efficiency.gp - efficiency T(1)/(n T(n)) against n, one line per hand-over cost.
# Called with: gnuplot -e "data='FILE'; out='PNG'; ttl='TITLE'; ncol=N" efficiency.gp
# FILE: whitespace table, header line "n H1 H2 ...", one row per n.
set terminal pngcairo size 720,460 noenhanced
set output out
set title ttl
set logscale x 2
set xlabel "processors n"
set ylabel "efficiency T(1) / (n T(n))"
set yrange [0:1.05]
set grid
set key outside right title "hand-over us"
set arrow from graph 0, first 0.85 to graph 1, first 0.85 nohead dt 2 lc rgb "gray40"
plot for [i=2:ncol] data using 1:i with linespoints title columnheader(i)
