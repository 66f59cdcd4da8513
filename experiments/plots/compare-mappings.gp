# compare-mappings.gp - busy time per node of several mappings side by side
# (experiments/compare-mappings). Variables: dat (folder of m-1.dat ... m-N.dat, columns rank and
# busy seconds, busiest first; m-I.mean, the mean; titles.txt, one "MAPPING|FIGURES" line each),
# out, n (mappings), top (the largest busy time, the shared y range), nodes.
set terminal pngcairo size (360 * n + 80),420 font 'DejaVu Sans,10' noenhanced
set output out
set multiplot layout 1,n title sprintf('busy time per node, busiest first (%d nodes); dashed: the mean', nodes)
set yrange [0:top * 1.08]
set xrange [-0.5:nodes - 0.5]
set grid ytics
set style fill solid 0.8 noborder
set boxwidth 0.8 relative
set xlabel 'nodes, busiest first'
set ylabel 'busy time (s)'
unset key
do for [i=1:n] {
    line = system(sprintf("sed -n %dp '%s/titles.txt'", i, dat))
    bar = strstrt(line, '|')
    set title line[1:bar - 1]."\n".line[bar + 1:] font ',10'
    mean = real(system(sprintf("cat '%s/m-%d.mean'", dat, i)))
    plot dat.'/m-'.i.'.dat' using 1:2 with boxes lc rgb '#3060c0', \
         mean with lines dt 2 lw 2 lc rgb '#d00000'
}
unset multiplot
