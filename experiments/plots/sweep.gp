# sweep.gp - the generic sweep's plot (experiments/sweep): the first axis on x, one line per
# combination of the other axes. Variables: dat (folder of series-1.dat ... series-N.dat, columns
# index, x value, y value), out, nseries, titles (space-separated, one per series), numeric (1
# when the x values are numbers: plotted at their value; 0: one tick per value, in order),
# xname, yname, ymin0 (1 when no y value is negative: the y axis starts at 0).
set terminal pngcairo size 800,560 font 'DejaVu Sans,10' noenhanced
set output out
set grid
set key below font ',9'
set xlabel xname
set ylabel yname
set title 'torusrt-sim sweep: '.yname.' against '.xname
# Offsets: left, right, top, bottom. An axis that starts at 0 gets no bottom offset, which would
# move it below 0.
if (ymin0) {
    set offsets graph 0.05, graph 0.05, graph 0.05, 0
    set yrange [0:*]
} else {
    set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
}
if (numeric) {
    plot for [i=1:nseries] dat.'/series-'.i.'.dat' using 2:3 with linespoints lw 2 pt 7 title word(titles, i)
} else {
    plot for [i=1:nseries] dat.'/series-'.i.'.dat' using 1:3:xtic(2) with linespoints lw 2 pt 7 title word(titles, i)
}
