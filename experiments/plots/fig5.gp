# fig5.gp - simulated image time against IP count, per mapping, with T(1)/n.
# Solid: the default reading (main); dashed: the other one (other, f56OTHER-SCENE-MAP.dat).
# Data: f56-SCENE-MAP.dat and f56OTHER-SCENE-MAP.dat, columns n,
# sim_time_s, load_balance, efficiency, t1_s.
load plotdir.'/common.gp'
load plotdir.'/flat.gp'
set multiplot layout 1, words(scenes) title 'Fig. 5: simulated image time against IP count (paper gives no numbers here; solid: '.main.', dashed: '.other.')'
set logscale y 10; set ylabel 'simulated image time (s)'; set format y '%g'
do for [s in scenes] {
    set title scenelabel(s)
    plot for [m in maps] file('f56', s, m) using 1:2 with linespoints lc rgb mapcolor(m) pt mappt(m) lw 2 title mapname(m), \
         for [m in maps] file('f56'.other, s, m) using 1:2 with linespoints lc rgb mapcolor(m) pt mappt(m) dt 2 lw 1 ps 0.6 notitle, \
         file('f56', s, 'cyclic') using 1:($5/$1) with lines lc rgb 'black' dt 3 lw 1.5 title 'ideal T(1)/n'
}
unset multiplot
