# sweep.gp - the generic sweep's plot (experiments/sweep): the first axis on x, one line per
# combination of the other axes. Variables: dat (folder of series-1.dat ... series-N.dat, columns
# index, x value, y value, and apart.dat: series number, x, y of the points drawn apart), out,
# nseries, titles (space-separated, one per series), numeric (1 when the x values are numbers:
# plotted at their value, with the ticks xtics; 0: one tick per value, in order), xlabel, ylabel,
# title, logx and logy (1: a logarithmic axis), free (1 when some point has the value that means
# no bound, e.g. --queue 0: drawn alone right of the others, its tick in xtics, not joined to the
# line), ymin0 (1 when no y value is negative: a linear y axis starts at 0).
set terminal pngcairo size 800,560 font 'DejaVu Sans,10' noenhanced
set output out
set grid
set key below font ',9'
set xlabel xlabel
set ylabel ylabel
set title title font ',10'
if (logx) { set logscale x }
if (logy) { set logscale y }
# Offsets: left, right, top, bottom. An axis that starts at 0 gets no bottom offset, which would
# move it below 0.
if (ymin0 && !logy) {
    set offsets graph 0.05, graph 0.05, graph 0.05, 0
    set yrange [0:*]
} else {
    set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
}
if (numeric) {
    eval 'set xtics '.xtics
    set autoscale xfix
    plot for [i=1:nseries] dat.'/series-'.i.'.dat' using 2:3 with linespoints lw 2 pt 7 lc i title word(titles, i), \
         for [i=1:nseries*free] dat.'/apart.dat' using 2:($1 == i ? $3 : 1/0) with points pt 9 ps 1.6 lc i notitle
} else {
    plot for [i=1:nseries] dat.'/series-'.i.'.dat' using 1:3:xtic(2) with linespoints lw 2 pt 7 lc i title word(titles, i)
}
