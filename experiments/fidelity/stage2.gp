# stage2.gp - the penalty fit: shared over replicated time at m = 64 against the bus cycle, one
# line per memory access time and image. Variables: dat (bus memory pen1 pen2), out.
set terminal pngcairo size 700, 420 font 'DejaVu Sans,10' noenhanced
set output out
set logscale x 2
set xlabel 'bus cycle (us)'
set ylabel 'shared / replicated at m = 64'
set key top left
set grid
set xrange [0.4:5]
plot for [m in "0.5 1 2"] dat using ($2 == m + 0 ? $1 : 1/0):3 with linespoints pt 7 title 'image 1, memory '.m.' us', \
     for [m in "0.5 1 2"] dat using ($2 == m + 0 ? $1 : 1/0):4 with linespoints pt 5 dt 2 title 'image 2, memory '.m.' us', \
     1.21 with lines lw 2 lc rgb 'black' title 'paper 1.21 (image 1)', \
     1.25 with lines lw 2 dt 3 lc rgb 'black' title 'paper 1.25 (image 2)'
