#!/usr/bin/env bash
# plot.sh - draw one PNG per figure from a sweep's CSVs (gnuplot, pngcairo).
#
#   experiments/plot.sh RESULTS_DIR
#
# Writes RESULTS/plots/fig5.png ... fig12.png (fig9, the cluster diagram, is not a result):
#   fig5   simulated image time against IP count (log-log), per mapping, with T(1)/n
#   fig6   system efficiency against IP count: busy-time definition (solid) and T(1)/(n T(n))
#          (dashed); the paper's "above 85 % for 16 IPs or fewer" marked
#   fig7   data memory requirement against IP count, with the pixel-partitioned line and the
#          paper's 1/6-1/7 at 16 IPs marked
#   fig8   preprocessing units against IP count, with the paper's 9438 / 738 / 432 marked
#   fig10  image time against processors per cluster m (16 clusters), paper's 64-per-cluster times
#   fig11  efficiency against m, the paper's "above 80 %" marks
#   fig12  data memory against m, with pixel-partitioned and the paper's ratios marked
# Only points with status ok are drawn; collect.sh's CSVs list the others.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
[ $# -eq 1 ] || die "usage: plot.sh RESULTS_DIR"
RES=$(cd "$1" && pwd)
command -v gnuplot >/dev/null || die "gnuplot is required"
for f in fig5_6 fig7 fig8 fig10_12; do [ -s "$RES/$f.csv" ] || die "$RES/$f.csv missing (run collect.sh first)"; done
OUT=$RES/plots
DAT=$OUT/data
mkdir -p "$DAT"
rm -f "$DAT"/*.dat

# series CSV NAME FILTER COLUMNS: write DAT/NAME.dat with the named columns of the ok rows
# matching FILTER ("col=value,col=value"); returns 0 even when no row matches (empty file).
series() {
    awk -F, -v filter="$3" -v cols="$4" '
        NR == 1 { for (i = 1; i <= NF; i++) ix[$i] = i
                  nf = split(filter, f, ","); nc = split(cols, c, ","); next }
        { if ($ix["status"] != "ok") next
          for (k = 1; k <= nf; k++) { split(f[k], kv, "="); if ($ix[kv[1]] != kv[2]) next }
          line = ""
          for (k = 1; k <= nc; k++) line = line (k > 1 ? " " : "") $ix[c[k]]
          print line }' "$1" >"$DAT/$2.dat"
}
nonempty() { [ -s "$DAT/$1.dat" ]; }

scenes=$(awk -F, 'NR > 1 { print $1 }' "$RES/fig5_6.csv" | sort -u | tr '\n' ' ')
maps=$(awk -F, 'NR > 1 { print $2 }' "$RES/fig5_6.csv" | sort -u | tr '\n' ' ')
cscenes=$(awk -F, 'NR > 1 { print $1 }' "$RES/fig10_12.csv" | sort -u | tr '\n' ' ')
datas=$(awk -F, 'NR > 1 { print $2 }' "$RES/fig10_12.csv" | sort -u | tr '\n' ' ')
for s in $scenes; do
    for m in $maps; do
        series "$RES/fig5_6.csv" "f56-$s-$m" "scene=$s,mapping=$m" n,sim_time_s,efficiency_busy,efficiency_t1,t1_s
        series "$RES/fig7.csv" "f7-$s-$m" "scene=$s,mapping=$m" n,total_bytes,pixel_partitioned_bytes
    done
    series "$RES/fig8.csv" "f8-$s" "scene=$s" n,units_parallel,units_serial
done
awk -F, 'NR > 1 && $7 != "" { print $2, $7 }' "$RES/fig8.csv" >"$DAT/f8-paper.dat"
for s in $cscenes; do
    for d in $datas; do
        series "$RES/fig10_12.csv" "f10-$s-$d" "scene=$s,data=$d" m,sim_time_s,efficiency_busy,efficiency_t1,total_bytes,pixel_partitioned_bytes,t1_s,processors
    done
done

label() { case $1 in image1) echo "image 1 (369 diffuse spheres)" ;; image2) echo "image 2 (glass + mirror, 121 spheres)" ;; *) echo "$1" ;; esac; }
mapname() { case $1 in block) echo "block" ;; cyclic) echo "load-balancing (cyclic)" ;; bc*) echo "block-cyclic b=${1#bc}" ;; *) echo "$1" ;; esac; }
mapstyle() { case $1 in block) echo "lc rgb '#d62728' pt 5" ;; cyclic) echo "lc rgb '#1f77b4' pt 7" ;; bc2) echo "lc rgb '#2ca02c' pt 9" ;; bc3) echo "lc rgb '#9467bd' pt 11" ;; *) echo "lc rgb 'gray30' pt 1" ;; esac; }
datastyle() { case $1 in replicated) echo "lc rgb '#1f77b4' pt 7" ;; shared) echo "lc rgb '#ff7f0e' pt 5" ;; *) echo "lc rgb 'gray30' pt 1" ;; esac; }
nscenes=$(echo $scenes | wc -w)
NMAX=$(awk -F, 'NR > 1 && $3 + 0 > m { m = $3 + 0 } END { print (m ? m : 1) * 1.3 }' "$RES/fig5_6.csv")
MMAX=$(awk -F, 'NR > 1 && $3 + 0 > m { m = $3 + 0 } END { print (m ? m : 1) * 1.3 }' "$RES/fig10_12.csv")
ncscenes=$(echo $cscenes | wc -w)

COMMON="set terminal pngcairo size $((560 * nscenes + 80)),640 font 'DejaVu Sans,10' noenhanced
set datafile missing ''
set grid
set key below font ',9' spacing 1.1 maxrows 4
set logscale x 2
set xtics (1, 2, 4, 8, 16, 32, 64, 128, 256, 512)
set xrange [0.8:$NMAX]
set xlabel 'intersection processors n (3D torus)'"

# Figure 5: image time.
{
    echo "$COMMON"
    echo "set output '$OUT/fig5.png'"
    echo "set multiplot layout 1,$nscenes title 'Fig. 5: simulated image time against IP count (paper gives no numbers here)'"
    echo "set logscale y 10; set ylabel 'simulated image time (s)'; set format y '%g'"
    for s in $scenes; do
        echo "set title '$(label "$s")'"
        p="plot"
        for m in $maps; do nonempty "f56-$s-$m" && p+=" '$DAT/f56-$s-$m.dat' using 1:2 with linespoints $(mapstyle "$m") lw 2 title '$(mapname "$m")',"; done
        nonempty "f56-$s-cyclic" && p+=" '$DAT/f56-$s-cyclic.dat' using 1:(\$5/\$1) with lines lc rgb 'black' dt 3 lw 1.5 title 'ideal T(1)/n',"
        echo "${p%,}"
    done
    echo "unset multiplot"
} | gnuplot

# Figure 6: efficiency, both definitions.
{
    echo "$COMMON"
    echo "set output '$OUT/fig6.png'"
    echo "set multiplot layout 1,$nscenes title 'Fig. 6: system efficiency against IP count (solid: busy / (n T(n)); dashed: T(1) / (n T(n)))'"
    echo "set ylabel 'efficiency (%)'; set yrange [0:105]"
    for s in $scenes; do
        echo "set title '$(label "$s")'"
        echo "\$p85 << EOD
1 85
16 85
EOD"
        p="plot \$p85 using 1:2 with lines lc rgb 'black' lw 4 title 'paper: > 85 % for n <= 16 (load-balancing)',"
        for m in $maps; do
            nonempty "f56-$s-$m" || continue
            p+=" '$DAT/f56-$s-$m.dat' using 1:(100*\$3) with linespoints $(mapstyle "$m") lw 2 title '$(mapname "$m")',"
            p+=" '$DAT/f56-$s-$m.dat' using 1:(100*\$4) with linespoints $(mapstyle "$m") dt 2 lw 1 ps 0.6 notitle,"
        done
        echo "${p%,}"
    done
    echo "unset multiplot"
} | gnuplot

# Figure 7: data memory against IP count.
{
    echo "$COMMON"
    echo "set output '$OUT/fig7.png'"
    echo "set multiplot layout 1,$nscenes title 'Fig. 7: data memory requirement (largest per-IP data x n) against IP count'"
    echo "set logscale y 10; set ylabel 'data memory requirement (KiB)'"
    for s in $scenes; do
        pp16=$(csv_value "$RES/fig7.csv" "scene=$s,n=16" pixel_partitioned_bytes)
        echo "set title '$(label "$s")'"
        p="plot"
        for m in $maps; do
            case $m in block|cyclic) lw=2 ;; *) lw=1 ;; esac
            nonempty "f7-$s-$m" && p+=" '$DAT/f7-$s-$m.dat' using 1:(\$2/1024) with linespoints $(mapstyle "$m") lw $lw title '$(mapname "$m")',"
        done
        nonempty "f7-$s-block" && p+=" '$DAT/f7-$s-block.dat' using 1:(\$3/1024) with lines lc rgb 'black' lw 2 dt 4 title 'pixel-partitioned (whole scene x n)',"
        if [ -n "$pp16" ]; then
            echo "\$paper << EOD
16 $(awk -v p="$pp16" 'BEGIN { print p / 6.5 / 1024, p / 7 / 1024, p / 6 / 1024 }')
EOD"
            p+=" \$paper using 1:2:3:4 with yerrorbars lc rgb 'black' pt 6 ps 2 lw 2 title 'paper at n = 16: 1/6 to 1/7 of pixel-partitioned',"
        fi
        echo "${p%,}"
    done
    echo "unset multiplot"
} | gnuplot

# Figure 8: preprocessing units.
{
    echo "$COMMON"
    echo "set terminal pngcairo size 700,640 font 'DejaVu Sans,10' noenhanced"
    echo "set output '$OUT/fig8.png'"
    echo "set title 'Fig. 8: parallel preprocessing time against IP count'"
    echo "set logscale y 10; set ylabel 'preprocessing time (units: one object vs one half-space test)'"
    echo "set key inside top right"
    p="plot"
    for s in $scenes; do
        case $s in image1) st="lc rgb '#1f77b4' pt 7 lw 2" ;; *) st="lc rgb '#2ca02c' pt 9 lw 1 dt 2" ;; esac
        nonempty "f8-$s" && p+=" '$DAT/f8-$s.dat' using 1:2 with linespoints $st title 'ours, $(label "$s")',"
    done
    nonempty f8-image1 && p+=" '$DAT/f8-image1.dat' using 1:(\$3/\$1) with lines lc rgb 'gray50' dt 3 title 'ours, image 1: serial / n',"
    nonempty f8-paper && p+=" '$DAT/f8-paper.dat' using 1:2 with points lc rgb 'black' pt 6 ps 2.5 lw 2 title 'paper, image 1: 9438 / 738 / 432',"
    p+=" '$DAT/f8-paper.dat' using 1:2:(sprintf('%d', \$2)) with labels offset 4,1 font ',9' notitle,"
    echo "${p%,}"
} | gnuplot

# Figures 10-12: clusters (left out when the sweep had none).
rm -f "$OUT"/fig10.png "$OUT"/fig11.png "$OUT"/fig12.png
if [ "$ncscenes" -gt 0 ]; then
CCOMMON="set terminal pngcairo size $((560 * ncscenes + 80)),640 font 'DejaVu Sans,10' noenhanced
set datafile missing ''
set grid
set key below font ',9' spacing 1.1 maxrows 4
set logscale x 2
set xtics (1, 2, 4, 8, 12, 16, 32, 64)
set xrange [0.8:$MMAX]
set xlabel 'processors per cluster m (16 clusters on a 4x2x2 torus: 16 m processors)'"
{
    echo "$CCOMMON"
    echo "set output '$OUT/fig10.png'"
    echo "set multiplot layout 1,$ncscenes title 'Fig. 10: simulated image time against processors per cluster'"
    echo "set logscale y 10; set ylabel 'simulated image time (s)'"
    for s in $cscenes; do
        echo "set title '$(label "$s")'"
        p="plot"
        for d in $datas; do
            nonempty "f10-$s-$d" && p+=" '$DAT/f10-$s-$d.dat' using 1:2 with linespoints $(datastyle "$d") lw 2 title 'ours, $d data',"
        done
        nonempty "f10-$s-replicated" && p+=" '$DAT/f10-$s-replicated.dat' using 1:(\$7/\$8) with lines lc rgb 'black' dt 3 title 'ideal T(1) / (16 m)',"
        case $s in
            image1) r=0.62 sh=0.75 ;;
            image2) r=1.34 sh=1.67 ;;
            *) r="" sh="" ;;
        esac
        if [ -n "$r" ]; then
            echo "\$paper << EOD
64 $r
EOD
\$papers << EOD
64 $sh
EOD"
            p+=" \$paper using 1:2 with points lc rgb '#1f77b4' pt 6 ps 2.5 lw 2 title 'paper, replicated, m = 64: $r s',"
            p+=" \$papers using 1:2 with points lc rgb '#ff7f0e' pt 4 ps 2.5 lw 2 title 'paper, shared, m = 64: $sh s',"
        fi
        echo "${p%,}"
    done
    echo "unset multiplot"
} | gnuplot
{
    echo "$CCOMMON"
    echo "set output '$OUT/fig11.png'"
    echo "set multiplot layout 1,$ncscenes title 'Fig. 11: efficiency against processors per cluster (solid: busy / (n T(n)); dashed: T(1) / (n T(n)))'"
    echo "set ylabel 'efficiency (%)'; set yrange [0:105]"
    for s in $cscenes; do
        echo "set title '$(label "$s")'"
        echo "\$p80 << EOD
1 80
12 80
EOD
\$p64 << EOD
64 80
EOD"
        p="plot \$p80 using 1:2 with lines lc rgb '#ff7f0e' lw 4 title 'paper: shared > 80 % up to m = 12',"
        p+=" \$p64 using 1:2 with points lc rgb '#1f77b4' pt 8 ps 2.5 lw 2 title 'paper: replicated > 80 % at m = 64',"
        for d in $datas; do
            nonempty "f10-$s-$d" || continue
            p+=" '$DAT/f10-$s-$d.dat' using 1:(100*\$3) with linespoints $(datastyle "$d") lw 2 title 'ours, $d',"
            p+=" '$DAT/f10-$s-$d.dat' using 1:(100*\$4) with linespoints $(datastyle "$d") dt 2 lw 1 ps 0.6 notitle,"
        done
        echo "${p%,}"
    done
    echo "unset multiplot"
} | gnuplot
{
    echo "$CCOMMON"
    echo "set output '$OUT/fig12.png'"
    echo "set multiplot layout 1,$ncscenes title 'Fig. 12: data memory requirement against processors per cluster'"
    echo "set logscale y 10; set ylabel 'data memory requirement, all processors (KiB)'"
    for s in $cscenes; do
        echo "set title '$(label "$s")'"
        rep12=$(csv_value "$RES/fig10_12.csv" "scene=$s,data=replicated,m=12" total_bytes)
        pp12=$(csv_value "$RES/fig10_12.csv" "scene=$s,data=replicated,m=12" pixel_partitioned_bytes)
        p="plot"
        for d in $datas; do
            nonempty "f10-$s-$d" && p+=" '$DAT/f10-$s-$d.dat' using 1:(\$5/1024) with linespoints $(datastyle "$d") lw 2 title 'ours, $d',"
        done
        for d in $datas; do
            nonempty "f10-$s-$d" && { p+=" '$DAT/f10-$s-$d.dat' using 1:(\$6/1024) with lines lc rgb 'black' lw 2 dt 4 title 'pixel-partitioned (whole scene x 16 m)',"; break; }
        done
        if [ -n "$rep12" ] && [ -n "$pp12" ]; then
            echo "\$paper << EOD
12 $(awk -v r="$rep12" -v p="$pp12" 'BEGIN { print r / 2 / 1024, (p / 12 < r / 2 ? p / 12 : r / 2) / 1024 }')
EOD"
            p+=" \$paper using 1:2 with points lc rgb '#ff7f0e' pt 10 ps 2.5 lw 2 title 'paper, m = 12: shared < 1/2 of replicated (our replicated / 2)',"
            echo "\$paperpp << EOD
12 $(awk -v p="$pp12" 'BEGIN { print p / 12 / 1024 }')
EOD"
            p+=" \$paperpp using 1:2 with points lc rgb 'black' pt 10 ps 2.5 lw 2 title 'paper, m = 12: shared < 1/12 of pixel-partitioned',"
        fi
        echo "${p%,}"
    done
    echo "unset multiplot"
} | gnuplot
fi
ls "$OUT"/fig*.png | sed 's/^/plot: /'
