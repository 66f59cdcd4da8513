# stage3.gp - the 1024-times fit: every combination of arrangement, interleave, hand-over and
# image 2, ranked by its score, with its two image times. Variables: dat (rank label t1 t2), out.
set terminal pngcairo size 900, 420 font 'DejaVu Sans,10' noenhanced
set output out
set xlabel 'combinations, best first'
set ylabel 'image time at 16 x 64 (s)'
set key top left
set grid
plot dat using 1:3 with points pt 7 ps 0.6 title 'image 1', \
     '' using 1:4 with points pt 5 ps 0.6 title 'image 2', \
     0.62 with lines lc rgb '#1f77b4' dt 2 title 'paper 0.62 s', \
     1.34 with lines lc rgb '#ff7f0e' dt 2 title 'paper 1.34 s'
