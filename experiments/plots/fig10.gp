# fig10.gp - image time against processors per cluster, with the paper's times at m = 64.
# Solid: the default reading main; dashed: the reading other (f10OTHER-SCENE-DATA.dat).
# Data: f10-SCENE-DATA.dat columns m, sim_time_s, load_balance, efficiency, total_bytes,
# pixel_partitioned_bytes, t1_s, processors; f10-paper-SCENE-DATA.dat (m, seconds),
# titled by the variable paper_SCENE_DATA.
load plotdir.'/common.gp'
load plotdir.'/clusters.gp'
set multiplot layout 1, words(scenes) title 'Fig. 10: simulated image time against processors per cluster (solid: '.main.', dashed: '.other.')'
set logscale y 10; set ylabel 'simulated image time (s)'
do for [s in scenes] {
    set title scenelabel(s)
    plot for [d in datas] file('f10', s, d) using 1:2 with linespoints lc rgb datacolor(d) pt datapt(d) lw 2 title 'ours, '.d.' data', \
         for [d in datas] file('f10'.other, s, d) using 1:2 with linespoints lc rgb datacolor(d) pt datapt(d) dt 2 lw 1 ps 0.6 notitle, \
         file('f10', s, 'replicated') using 1:($7/$8) with lines lc rgb 'black' dt 3 title 'ideal T(1) / (16 m)', \
         for [d in datas] file('f10-paper', s, d) using 1:2 with points lc rgb datacolor(d) pt (d eq 'shared' ? 4 : 6) ps 2.5 lw 2 title value('paper_'.s.'_'.d)
}
unset multiplot
