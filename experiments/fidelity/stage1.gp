# stage1.gp - the units fit: image 1's preprocessing units on 1, 16 and 32 IPs for each layout
# and counting rule, against the paper's. Variables: dat (layout rule u1 u16 u32 score), out.
set terminal pngcairo size 900, 420 font 'DejaVu Sans,10' noenhanced
set output out
set datafile separator whitespace
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set logscale y
set ylabel 'units (log scale)'
set xtics rotate by -30 font ',8'
set key top right
set grid ytics
plot dat using 3:xtic(sprintf('%s/%s', strcol(1), strcol(2))) title '1 IP' lc rgb '#1f77b4', \
     '' using 4 title '16 IPs' lc rgb '#2ca02c', \
     '' using 5 title '32 IPs' lc rgb '#9467bd', \
     9438 with lines dt 2 lc rgb '#1f77b4' title 'paper 9438', \
     738 with lines dt 2 lc rgb '#2ca02c' title 'paper 738', \
     432 with lines dt 2 lc rgb '#9467bd' title 'paper 432'
