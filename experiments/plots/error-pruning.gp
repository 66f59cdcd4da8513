# error-pruning.gp - the shade-tree pruning study (docs/error-vs-runtime.md): PSNR against
# simulated image time and wall time, for the max-depth and the min-weight sweeps (2 x 2).
# Variables (python3 experiments/report error-vs-runtime): dat, out, nseries, title1..titleN,
# labelled (one word per series: 1 = label the points with their setting, the renderer's).
# Data: dat/pI.max_depth.dat and dat/pI.min_weight.dat columns image_time_s, wall_s, psnr_db
# ('inf' for identical images), setting.
cap = 100   # PSNR drawn here when infinite (identical images)
psnr(c) = strcol(c) eq 'inf' ? cap : column(c)
series(i) = value('title'.i)
setting(i) = word(labelled, i) eq '1' ? strcol(4) : ''
set terminal pngcairo enhanced font 'Sans,10' size 1300,1050
set output out
set multiplot layout 2,2 title "Shade-tree pruning: PSNR against the default-settings image (max-depth 8, min-weight 1/512)\nidentical images (PSNR = inf) drawn at 100 dB; labels on the renderer's points give the setting"
set grid
set key below horizontal maxcols 3 font ',8'
set yrange [*:cap+8]
set logscale x
set ylabel 'PSNR, dB'
set xlabel 'simulated image time, s'
set title 'max-depth 0..8 (min-weight 1/512)'
plot for [i=1:nseries] dat.'/p'.i.'.max_depth.dat' using 1:(psnr(3)) with linespoints pt 7 lc i title series(i), \
     for [i=1:nseries] dat.'/p'.i.'.max_depth.dat' using 1:(psnr(3)):(setting(i)) with labels offset 0,0.9 font ',8' tc lt i notitle
set xlabel 'wall-clock s (fastest of the repetitions)'
set title 'max-depth 0..8 (min-weight 1/512)'
plot for [i=1:nseries] dat.'/p'.i.'.max_depth.dat' using 2:(psnr(3)) with points pt 7 lc i title series(i)
set xlabel 'simulated image time, s'
set title 'min-weight 1/512..1/8 (max-depth 8)'
plot for [i=1:nseries] dat.'/p'.i.'.min_weight.dat' using 1:(psnr(3)) with linespoints pt 9 lc i title series(i), \
     for [i=1:nseries] dat.'/p'.i.'.min_weight.dat' using 1:(psnr(3)):(setting(i)) with labels offset 0,0.9 font ',8' tc lt i notitle
set xlabel 'wall-clock s (fastest of the repetitions)'
set title 'min-weight 1/512..1/8 (max-depth 8)'
plot for [i=1:nseries] dat.'/p'.i.'.min_weight.dat' using 2:(psnr(3)) with points pt 9 lc i title series(i)
unset multiplot
