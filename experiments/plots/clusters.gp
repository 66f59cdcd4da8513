# clusters.gp - the x axis of the cluster figures (10 to 12): processors per cluster m.
set xtics (1, 2, 4, 8, 12, 16, 32, 64)
set xrange [0.8:xmax]
set xlabel 'processors per cluster m (16 clusters on a 4x2x2 torus: 16 m processors)'
