#!/usr/bin/env bash
# Makes docs/img/series-paper-image1-512.png: the statistics over time (--stats-interval) of
# paper-image1 at 144x144 on 512 IPs (scatter, rays-first), plotted with the README's gnuplot
# recipe and a title. Usage: scripts/series_picture.sh [BUILD_DIR]   (default build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$build/torusrt-sim" "$root/scenes/paper-image1.nff" --ips 8x8x8 --map scatter --queue-order rays-first --t1 1 \
    -o a.png --stats r.json --stats-interval 10ms -q
gnuplot -e "set datafile separator ','; set terminal pngcairo size 900,420; set output 'series.png';
  set title 'paper-image1, 144x144, 512 IPs (8x8x8, scatter, rays-first), 10 ms intervals';
  set xlabel 'simulated time (s)'; set ylabel 'share'; set y2label 'packets'; set y2tics; set key top right;
  plot 'r.series.csv' using 1:3 with steps lw 2 title 'IP busy share',
       '' using 1:8 with steps title 'busiest link use', '' using 1:5 axes x1y2 with steps title 'packets queued'"
cp series.png "$root/docs/img/series-paper-image1-512.png.tmp"
mv "$root/docs/img/series-paper-image1-512.png.tmp" "$root/docs/img/series-paper-image1-512.png"
echo "series_picture: wrote docs/img/series-paper-image1-512.png"
