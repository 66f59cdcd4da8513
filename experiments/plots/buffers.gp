# buffers.gp - the buffer study's plot: image time over the unbounded run's against buffer
# capacity, one line per scene and machine. Set by the caller (experiments/report/buffers.py):
# dat (folder of the .dat files), out (the PNG), series (space-separated .dat names).
set terminal pngcairo size 760, 600 font 'DejaVu Sans,10' noenhanced
set output out
set grid
set logscale x 2
set xrange [0.8:160]
set xtics ('1' 1, '2' 2, '4' 4, '8' 8, '16' 16, '32' 32, '64' 64, 'unbounded' 128)
set xlabel 'packets per buffer of each class (--queue)'
set ylabel 'image time / unbounded image time'
set key below font ',9' maxrows 4
plot for [s in series] dat.'/'.s.'.dat' using 1:2 with linespoints title s
