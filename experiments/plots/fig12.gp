# fig12.gp - data memory against processors per cluster, with pixel-partitioned and the paper's
# m = 12 statements. Data: f10-SCENE-DATA.dat as fig10; f12-paper-SCENE.dat (m, half of our
# replicated, 1/12 of pixel-partitioned, in KiB).
load plotdir.'/common.gp'
load plotdir.'/clusters.gp'
set multiplot layout 1, words(scenes) title 'Fig. 12: data memory requirement against processors per cluster'
set logscale y 10; set ylabel 'data memory requirement, all processors (KiB)'
do for [s in scenes] {
    set title scenelabel(s)
    plot for [d in datas] file('f10', s, d) using 1:($5/1024) with linespoints lc rgb datacolor(d) pt datapt(d) lw 2 title 'ours, '.d, \
         file('f10', s, word(datas, 1)) using 1:($6/1024) with lines lc rgb 'black' lw 2 dt 4 title 'pixel-partitioned (whole scene x 16 m)', \
         dat.'/f12-paper-'.s.'.dat' using 1:2 with points lc rgb '#ff7f0e' pt 10 ps 2.5 lw 2 title paper_half, \
         dat.'/f12-paper-'.s.'.dat' using 1:3 with points lc rgb 'black' pt 10 ps 2.5 lw 2 title paper_twelfth
}
unset multiplot
