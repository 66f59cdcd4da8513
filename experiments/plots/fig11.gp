# fig11.gp - efficiency T(1)/(n T(n)) against processors per cluster, the readings main (solid)
# and other (dashed, f10OTHER-SCENE-DATA.dat), with the paper's 80 % statements.
# Data: f10-SCENE-DATA.dat as fig10; paper-shared-floor.dat and paper-replicated-floor.dat (m, percent).
load plotdir.'/common.gp'
load plotdir.'/clusters.gp'
set multiplot layout 1, words(scenes) title 'Fig. 11: efficiency T(1) / (n T(n)) against processors per cluster (solid: '.main.', dashed: '.other.')'
set ylabel 'efficiency (%)'; set yrange [0:105]
do for [s in scenes] {
    set title scenelabel(s)
    plot dat.'/paper-shared-floor.dat' using 1:2 with lines lc rgb '#ff7f0e' lw 4 title paper_shared_floor, \
         dat.'/paper-replicated-floor.dat' using 1:2 with points lc rgb '#1f77b4' pt 8 ps 2.5 lw 2 title paper_replicated_floor, \
         for [d in datas] file('f10', s, d) using 1:(100*$4) with linespoints lc rgb datacolor(d) pt datapt(d) lw 2 title 'ours, '.d, \
         for [d in datas] file('f10'.other, s, d) using 1:(100*$4) with linespoints lc rgb datacolor(d) pt datapt(d) dt 2 lw 1 ps 0.6 notitle
}
unset multiplot
