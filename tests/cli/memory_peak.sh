#!/usr/bin/env bash
# memory_peak.sh - the memory budget holds for the process as a whole: peak resident memory
# (/usr/bin/time -v) stays within --memory-budget plus the fixed overhead docs/cli.md states
# (64 MiB for code, SystemC and the scene). Cases: the exponential shade tree of paper-image2
# (--min-weight 0 --max-depth 1000), refused from the materials before rendering, naming both
# options; paper-image2 rendered whole within a 64M budget; a run whose packets pass a small
# budget; 100000 coincident spheres, refused before their cell lists are made; and a diffuse
# scene, which is never refused at any depth; and an animation of 24 large frames, which keeps
# none of them in memory.
#
# Usage (CTest runs it so): bash tests/cli/memory_peak.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-render torusrt-sim
time_limit 300
[ -x /usr/bin/time ] || { echo "SKIP: /usr/bin/time is not installed (Debian package time)"; exit 0; }
overhead_kb=$((64 * 1024))
paper2="$SRC/scenes/paper-image2.nff"

# peak NAME BUDGET_MB EXPECTED_RC EXE ARGS...: runs EXE, checks its exit status and that its
# peak resident memory is at most BUDGET_MB MiB plus the overhead; stderr in $TMP/NAME.stderr.
peak() {
    local name=$1 budget_mb=$2 want_rc=$3 exe=$4
    shift 4
    "${run_limited[@]}" /usr/bin/time -v -o "$TMP/$name.time" "$BUILD/$exe" "$@" -q \
        >/dev/null 2>"$TMP/$name.stderr" </dev/null
    local rc=$?
    check "$name: exit status $rc, expected $want_rc ($(head -c 300 "$TMP/$name.stderr"))" [ "$rc" -eq "$want_rc" ]
    local kb
    kb=$(awk -F: '/Maximum resident set size/ { gsub(/ /, "", $2); print $2 }' "$TMP/$name.time")
    check "$name: no peak memory in /usr/bin/time's report" [ -n "$kb" ]
    check "$name: peak $kb KiB over the $budget_mb MiB budget plus $((overhead_kb / 1024)) MiB" \
        [ "${kb:-0}" -le $((budget_mb * 1024 + overhead_kb)) ]
}

for exe in torusrt-sim torusrt-render; do
    peak "$exe-tree" 64 1 $exe "$paper2" -o "$TMP/tree.png" --memory-budget 64M --min-weight 0 --max-depth 1000
    check "$exe-tree: message names --max-depth and --min-weight: $(head -c 300 "$TMP/$exe-tree.stderr")" \
        grep -q -- "--max-depth 1000 and --min-weight 0" "$TMP/$exe-tree.stderr"
    check "$exe-tree: left an image" [ ! -e "$TMP/tree.png" ]
done

peak sim-whole 64 0 torusrt-sim "$paper2" -o "$TMP/whole-sim.png" --memory-budget 64M
"$BUILD/torusrt-render" "$paper2" -o "$TMP/whole-render.png" -q || fail "paper-image2 render"
check "paper-image2 within 64M: the simulator's image differs from the renderer's" \
    cmp -s "$TMP/whole-sim.png" "$TMP/whole-render.png"
peak sim-packets 40 1 torusrt-sim "$paper2" -o "$TMP/packets.png" --size 1024x1024 --memory-budget 40M

{
    printf 'v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 8 8\nl 1 1 5\nf 1 1 1 1 0 0 0 1\n'
    awk 'BEGIN { for (i = 0; i < 100000; i++) print "s 0 0 0 1" }'
} >"$TMP/coincident.nff"
peak sim-coincident 64 1 torusrt-sim "$TMP/coincident.nff" -o "$TMP/coincident.png"
check "coincident spheres: not refused for their cell lists: $(head -c 300 "$TMP/sim-coincident.stderr")" \
    grep -q "memory budget exceeded: the cell lists" "$TMP/sim-coincident.stderr"

printf 'v from 0 3 6 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 8 8\nl 4 6 4\nf 0.8 0.8 0.8 1 0 0 0 1\np 4 -5 0 -5 5 0 -5 5 0 5 -5 0 5\ns 0 1 0 1\n' \
    >"$TMP/diffuse.nff"
for exe in torusrt-sim torusrt-render; do
    peak "$exe-diffuse" 1 0 $exe "$TMP/diffuse.nff" -o "$TMP/diffuse-$exe.png" --memory-budget 1M \
        --min-weight 0 --max-depth 1000
done

# An animation keeps no frame: each goes to its temporary as it completes. 24 frames of
# 1024x1024 (3 MiB each as 8-bit RGB, 72 MiB together) peak within an 80M budget, and no higher
# than 2 frames of the same do, give or take a frame and a half.
printf 'v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 1024 1024
l 1 1 5
f 1 1 1 1 0 0 0 1
s 0 0 0 0.01
' \
    >"$TMP/speck.nff"
mkdir "$TMP/f24" "$TMP/f2"
peak sim-frames-24 80 0 torusrt-sim "$TMP/speck.nff" -o "$TMP/f24/f_%02d.png" --orbit 90 --frames 24 \
    --memory-budget 80M
peak sim-frames-2 80 0 torusrt-sim "$TMP/speck.nff" -o "$TMP/f2/f_%02d.png" --orbit 90 --frames 2 \
    --memory-budget 80M
check "24 frames: 24 files" [ "$(ls "$TMP/f24" | wc -l)" -eq 24 ]
kb24=$(awk -F: '/Maximum resident set size/ { gsub(/ /, "", $2); print $2 }' "$TMP/sim-frames-24.time")
kb2=$(awk -F: '/Maximum resident set size/ { gsub(/ /, "", $2); print $2 }' "$TMP/sim-frames-2.time")
check "24 frames peak at $kb24 KiB against 2 frames' $kb2 KiB" [ "${kb24:-0}" -le $((${kb2:-0} + 4608)) ]
# A budget too small for the frame buffer and one frame's image refuses the animation at once.
peak sim-frames-small 8 1 torusrt-sim "$TMP/speck.nff" -o "$TMP/f2/g_%02d.png" --orbit 90 --frames 40 \
    --memory-budget 8M
check "small budget: the message names the budget" grep -q "memory budget exceeded" "$TMP/sim-frames-small.stderr"
finish
