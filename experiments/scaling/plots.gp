# plots.gp - the scaling study's pictures (drawn by experiments/scaling/report.py).
# Called with: gnuplot -e "kind='time|memory|busy|share'; data='FILE'; out='PNG'; ttl='TITLE'; ncol=N" plots.gp
#   time:   FILE has a header "n MACHINE1 ..." and one row per n: image time against processors.
#   memory: FILE has rows "MACHINE n total_bytes time_s": image time against total data memory,
#           one point per machine and n, the n as the point's label.
#   busy:   FILE has a header "rank SERIES1 ..." and one row per node rank (busiest first).
#   share:  FILE has a header "t SERIES1 ..." and one row per time bin: the share of busy IPs.
set terminal pngcairo size 860,520 font 'DejaVu Sans,10' noenhanced
set output out
set title ttl
set grid
set datafile missing '-'
if (kind eq 'time') {
    set logscale xy
    set xlabel "processors n"
    set ylabel "image time (s)"
    set key outside right font ',9'
    plot for [i=2:ncol] data using 1:i with linespoints title columnheader(i)
}
if (kind eq 'memory') {
    set logscale xy
    set xlabel "total data memory (bytes)"
    set ylabel "image time (s)"
    set key outside right font ',9'
    plot for [n in "16 64 512 4096"] data using ($2 == n + 0 ? $3 : 1/0):4 with points pt 7 ps 1.2 title "n = ".n
}
if (kind eq 'busy') {
    set xlabel "node, busiest first"
    set ylabel "busy time (s)"
    set key top right
    plot for [i=2:ncol] data using 1:i with lines lw 2 title columnheader(i)
}
if (kind eq 'share') {
    set xlabel "simulated time (s)"
    set ylabel "busy processors (%)"
    set yrange [0:100]
    set key top right
    plot for [i=2:ncol] data using 1:(100 * column(i)) with steps lw 2 title columnheader(i)
}
