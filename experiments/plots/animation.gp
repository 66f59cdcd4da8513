# animation.gp - image time per frame for each mapping policy, one panel per scene and node
# count. Variables set by the caller (experiments/report/animation.py): dat (folder of the .dat
# files, one per scene and n: frame, then one column per policy), out (the PNG), panels
# (space-separated SCENE-N), policies (space-separated, in the .dat's column order).
set terminal pngcairo size 1200, 900 font 'DejaVu Sans,10' noenhanced
set output out
set datafile missing ''
set grid
set key top right font ',9'
set xlabel 'frame (360-degree orbit)'
set ylabel 'image time (s, simulated)'
policycolor(p) = p eq 'cyclic' ? '#1f77b4' : p eq 'cost' ? '#ff7f0e' : p eq 'every-frame' ? '#2ca02c' : p eq 'adaptive' ? '#d62728' : p eq 'preview' ? '#9467bd' : 'gray30'
set multiplot layout 2, 2
do for [panel in panels] {
  set title panel
  file = dat.'/frames-'.panel.'.dat'
  plot for [i = 1:words(policies)] file using 1:(column(i + 1)) with linespoints pt 7 ps 0.5 \
       lc rgb policycolor(word(policies, i)) title word(policies, i)
}
unset multiplot
