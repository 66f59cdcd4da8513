# plots.gp - the motion study's pictures (drawn by experiments/motion/report.py).
# Called with: gnuplot -e "kind='frames|strip'; data='FILE'; out='PNG'; ttl='TITLE'; ncol=N" plots.gp
#   frames: FILE has a header "frame SERIES1 ..." and one row per frame: time per frame per policy,
#           the last series (the list update alone) dashed.
#   strip:  FILE lists PNG frames, one path a line, ncol of them: drawn as rows of 8.
if (kind eq 'frames') {
    set terminal pngcairo size 860,480 font 'DejaVu Sans,10' noenhanced
    set output out
    set title ttl
    set grid
    set datafile missing '-'
    set xlabel "frame"
    set ylabel "frame time (s)"
    set yrange [0:*]
    set key outside right font ',9'
    plot for [i=2:ncol-1] data using 1:i with lines lw 2 title columnheader(i), \
         data using 1:ncol with lines lw 2 dt 2 lc "black" title columnheader(ncol)
}
if (kind eq 'strip') {
    cols = 8
    rows = (ncol + cols - 1) / cols
    set terminal pngcairo size cols * 130, rows * 130 noenhanced
    set output out
    files = system('cat '.data)
    unset border
    unset tics
    unset key
    set size ratio -1
    set multiplot layout rows, cols margins 0.005, 0.995, 0.01, 0.99 spacing 0.01, 0.02
    do for [i = 1:ncol] {
        plot word(files, i) binary filetype=png with rgbimage notitle
    }
    unset multiplot
}
