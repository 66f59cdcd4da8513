# fig8.gp - preprocessing units against IP count, with the paper's image-1 figures.
# Data: f8-image1.dat and f8-image2.dat columns n, units_parallel, units_serial; f8-paper.dat (n, units), its title paper_units.
load plotdir.'/common.gp'
load plotdir.'/flat.gp'
set terminal pngcairo size 700,640 font 'DejaVu Sans,10' noenhanced
set output out
set title 'Fig. 8: parallel preprocessing time against IP count'
set logscale y 10; set ylabel 'preprocessing time (units: one object vs one half-space test)'
set key inside top right
plot dat.'/f8-image1.dat' using 1:2 with linespoints lc rgb '#1f77b4' pt 7 lw 2 title 'ours, '.scenelabel('image1'), \
     dat.'/f8-image2.dat' using 1:2 with linespoints lc rgb '#2ca02c' pt 9 lw 1 dt 2 title 'ours, '.scenelabel('image2'), \
     dat.'/f8-image1.dat' using 1:($3/$1) with lines lc rgb 'gray50' dt 3 title 'ours, image 1: serial / n', \
     dat.'/f8-paper.dat' using 1:2 with points lc rgb 'black' pt 6 ps 2.5 lw 2 title paper_units, \
     dat.'/f8-paper.dat' using 1:2:(sprintf('%d', $2)) with labels offset 4,1 font ',9' notitle
