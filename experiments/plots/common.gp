# common.gp - settings and names shared by the reproduction plots (loaded by each fig*.gp).
# Variables set by the caller (python3 experiments/report plots): dat (folder of the .dat files
# written from the CSVs), out (the PNG), scenes (space-separated), lb_main and lb_other (the
# readings' load-balancing interleaves), and per plot its series.
set terminal pngcairo size 560 * words(scenes) + 80, 640 font 'DejaVu Sans,10' noenhanced
set datafile missing ''
set grid
set key below font ',9' spacing 1.1 maxrows 4
set logscale x 2
set output out

scenelabel(s) = s eq 'image1' ? 'image 1 (369 diffuse spheres)' : s eq 'image2' ? 'image 2 (glass + mirror, 121 spheres)' : s
# The load-balancing series runs each reading's interleave: lb_main (solid) and lb_other (dashed).
if (!exists("lb_main")) lb_main = 'cyclic'
if (!exists("lb_other")) lb_other = lb_main
lbname = lb_other eq lb_main ? 'load-balancing ('.lb_main.')' : 'load-balancing ('.lb_main.'; dashed '.lb_other.')'
mapname(m) = m eq 'block' ? 'block' : m eq 'cyclic' ? lbname : m[1:2] eq 'bc' ? 'block-cyclic b='.m[3:] : m
mapcolor(m) = m eq 'block' ? '#d62728' : m eq 'cyclic' ? '#1f77b4' : m eq 'bc2' ? '#2ca02c' : m eq 'bc3' ? '#9467bd' : 'gray30'
mappt(m) = m eq 'block' ? 5 : m eq 'cyclic' ? 7 : m eq 'bc2' ? 9 : m eq 'bc3' ? 11 : 1
datacolor(d) = d eq 'replicated' ? '#1f77b4' : d eq 'shared' ? '#ff7f0e' : 'gray30'
datapt(d) = d eq 'replicated' ? 7 : d eq 'shared' ? 5 : 1
file(prefix, s, m) = dat.'/'.prefix.'-'.s.'-'.m.'.dat'
