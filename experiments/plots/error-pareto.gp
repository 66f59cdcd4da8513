# error-pareto.gp - the timing-style study's trade (docs/error-vs-runtime.md): per configuration,
# every run (AT and LT at every quantum) as wall time against |error of sim_time_s|, and the
# runs no other run of the configuration beats on both (the Pareto front) joined by a line.
# Variables (python3 experiments/report error-vs-runtime): dat, out, nconf, title1..titleN, wmin wmax.
# Data: dat/allI.dat and dat/frontI.dat, columns wall_s, |error| % (0 drawn at the floor), quantum.
floor = 1e-5
mag(x) = x == 0 ? floor : x
conf(i) = value('title'.i)
set terminal pngcairo enhanced font 'Sans,10' size 1000,700
set output out
set title "Loosely timed against approximately timed: wall time against image-time error\n(every run a point, the Pareto front a line; squares = AT, error 0, drawn at 1e-5 %; dotted lines 1 %, 5 %)"
set logscale xy
set xrange [wmin:wmax]
set yrange [floor/2:200]
set format y "%g"
set grid
set key outside right font ',9'
set xlabel 'wall-clock s (fastest of the repetitions)'
set ylabel '|error of sim\_time\_s| %'
set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead lc 'gray40' dt 3
set arrow 2 from graph 0, first 5 to graph 1, first 5 nohead lc 'gray40' dt 3
plot for [i=1:nconf] dat.'/front'.i.'.dat' using 1:(mag($2)) with linespoints pt 7 ps 1.0 lc i title conf(i), \
     for [i=1:nconf] dat.'/all'.i.'.dat' using 1:(mag($2)) with points pt 6 ps 0.7 lc i notitle, \
     for [i=1:nconf] dat.'/at'.i.'.dat' using 1:(floor) with points pt 5 ps 1.6 lc i notitle
