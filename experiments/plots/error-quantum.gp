# error-quantum.gp - the timing-style study (docs/error-vs-runtime.md): |error| of sim_time_s and
# efficiency_busy against wall time and speed-up (2 x 2), then against the quantum (second PNG).
# Variables (python3 experiments/report error-vs-runtime): dat, out, out_q, nconf, title1..titleN,
# wmin wmax smin smax qmin qmax (axis ranges). Data: dat/qI.dat columns wall_s, speedup,
# err_time_pct, err_eff_pct (signed), quantum_s, quantum (the LT runs of configuration I);
# dat/atI.dat: the AT run's wall_s.
floor = 1e-5   # |error| drawn here when it is exactly 0 (log axis)
mag(x) = abs(x) == 0 ? floor : abs(x)
side(x) = x < 0 ? 6 : 7   # open point: LT under AT; filled: over
conf(i) = value('title'.i)
set terminal pngcairo enhanced font 'Sans,10' size 1200,900
set output out
set datafile missing NaN
set multiplot layout 2,2 title "Loosely-timed (LT) against approximately-timed (AT) runs of torusrt-sim: error against run time\n(|error| %, log scale; filled = LT over AT, open = LT under; exactly 0 drawn at 1e-5 %; squares = AT; dotted lines 1 %, 5 %, dashed 20 %)"
set logscale y
set yrange [floor/2:200]
set format y "%g"
set grid
set key top right font ',8' opaque box
set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead lc 'gray40' dt 3
set arrow 2 from graph 0, first 5 to graph 1, first 5 nohead lc 'gray40' dt 3
set arrow 3 from graph 0, first 20 to graph 1, first 20 nohead lc 'gray20' dt 2
set logscale x
set xrange [wmin:wmax]
set xlabel 'wall-clock s (fastest of the repetitions)'
set ylabel '|error of sim\_time\_s| %'
plot for [i=1:nconf] dat.'/q'.i.'.dat' using 1:(mag($3)):(side($3)) with linespoints pt variable ps 1.2 lc i title conf(i), \
     for [i=1:nconf] dat.'/at'.i.'.dat' using 1:(floor) with points pt 5 ps 1.6 lc i notitle
set ylabel '|error of efficiency\_busy| %'
plot for [i=1:nconf] dat.'/q'.i.'.dat' using 1:(mag($4)):(side($4)) with linespoints pt variable ps 1.2 lc i title conf(i), \
     for [i=1:nconf] dat.'/at'.i.'.dat' using 1:(floor) with points pt 5 ps 1.6 lc i notitle
unset logscale x
set xrange [smin:smax]
set key top left
set xlabel 'speed-up over AT (AT wall s / LT wall s)'
set ylabel '|error of sim\_time\_s| %'
plot for [i=1:nconf] dat.'/q'.i.'.dat' using 2:(mag($3)):(side($3)) with linespoints pt variable ps 1.2 lc i title conf(i)
set ylabel '|error of efficiency\_busy| %'
plot for [i=1:nconf] dat.'/q'.i.'.dat' using 2:(mag($4)):(side($4)) with linespoints pt variable ps 1.2 lc i title conf(i)
unset multiplot
set output out_q
set terminal pngcairo enhanced font 'Sans,10' size 900,560
set title "Error against the LT global quantum (solid: sim_time_s, dashed: efficiency_busy; open = LT under AT)" noenhanced
set logscale x
set xrange [qmin:qmax]
set key top left
set format x "%g"
set xlabel 'global quantum, s'
set ylabel '|error| %'
plot for [i=1:nconf] dat.'/q'.i.'.dat' using ($5 > 0 ? $5 : NaN):(mag($3)):(side($3)) with linespoints pt variable ps 1.2 lc i title conf(i), \
     for [i=1:nconf] dat.'/q'.i.'.dat' using ($5 > 0 ? $5 : NaN):(mag($4)):(side($4)) with linespoints pt variable ps 1.2 lc i dt 2 notitle
