#!/usr/bin/env bash
# Makes docs/img/trace-gtkwave.png: a 2x2 torus trace of paper-image1 opened from its save file in
# the real GTKWave on a virtual X display, written by GTKWave itself (File > Grab To File).
# Usage: scripts/trace_picture.sh [BUILD_DIR]   (default build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$build/torusrt-sim" "$root/scenes/paper-image1.nff" --size 48x48 --ips 2x2 -o t.png --vcd t.vcd --trace-ips 0,1 -q
# The dump is named relatively (-f t.vcd), so the window's title shows t.vcd, not this scratch folder.
timeout 120 xvfb-run -a -s "-screen 0 1400x900x24" gtkwave -f t.vcd -a t.gtkw -S "$root/scripts/trace_picture.tcl" \
    > gtkwave.log 2>&1 || { cat gtkwave.log >&2; exit 1; }
[ -s trace.png ] || { echo "trace_picture: GTKWave wrote no picture" >&2; cat gtkwave.log >&2; exit 1; }
cp trace.png "$root/docs/img/trace-gtkwave.png.tmp"
mv "$root/docs/img/trace-gtkwave.png.tmp" "$root/docs/img/trace-gtkwave.png"
echo "trace_picture: wrote docs/img/trace-gtkwave.png"
