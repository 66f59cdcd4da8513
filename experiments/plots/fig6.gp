# fig6.gp - efficiency T(1)/(n T(n)) against IP count: the default reading main (solid) and
# the reading other (dashed, f56OTHER-SCENE-MAP.dat), with the paper's floor. Data: f56-SCENE-MAP.dat as fig5; paper-floor.dat (n, percent), its title paper_floor.
load plotdir.'/common.gp'
load plotdir.'/flat.gp'
set multiplot layout 1, words(scenes) title 'Fig. 6: system efficiency T(1) / (n T(n)) against IP count (solid: '.main.', dashed: '.other.')'
set ylabel 'efficiency (%)'; set yrange [0:105]
do for [s in scenes] {
    set title scenelabel(s)
    plot dat.'/paper-floor.dat' using 1:2 with lines lc rgb 'black' lw 4 title paper_floor, \
         for [m in maps] file('f56', s, m) using 1:(100*$4) with linespoints lc rgb mapcolor(m) pt mappt(m) lw 2 title mapname(m), \
         for [m in maps] file('f56'.other, s, m) using 1:(100*$4) with linespoints lc rgb mapcolor(m) pt mappt(m) dt 2 lw 1 ps 0.6 notitle
}
unset multiplot
