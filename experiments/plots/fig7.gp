# fig7.gp - data memory requirement against IP count, with pixel-partitioned and the paper's ratio.
# Data: f7-SCENE-MAP.dat columns n, total_bytes, pixel_partitioned_bytes; f7-paper-SCENE.dat
# (n, middle, low, high in KiB), its title paper_ratio.
load plotdir.'/common.gp'
load plotdir.'/flat.gp'
set multiplot layout 1, words(scenes) title 'Fig. 7: data memory requirement (largest per-IP data x n) against IP count'
set logscale y 10; set ylabel 'data memory requirement (KiB)'
do for [s in scenes] {
    set title scenelabel(s)
    plot for [m in maps] file('f7', s, m) using 1:($2/1024) with linespoints lc rgb mapcolor(m) pt mappt(m) lw (m eq 'block' || m eq 'cyclic' ? 2 : 1) title mapname(m), \
         file('f7', s, 'block') using 1:($3/1024) with lines lc rgb 'black' lw 2 dt 4 title 'pixel-partitioned (whole scene x n)', \
         dat.'/f7-paper-'.s.'.dat' using 1:2:3:4 with yerrorbars lc rgb 'black' pt 6 ps 2 lw 2 title paper_ratio
}
unset multiplot
