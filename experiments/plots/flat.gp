# flat.gp - the x axis of the flat-torus figures (5 to 8): IP count n.
set xtics (1, 2, 4, 8, 16, 32, 64, 128, 256, 512)
set xrange [0.8:xmax]
set xlabel 'intersection processors n (3D torus)'
