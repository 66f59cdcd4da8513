#!/usr/bin/env bash
# budget_needs.sh - what the memory budget's messages count, and the time series inside the
# budget: the packets a frame needs as it is set up are all of its primaries entering the space
# (not one more than the budget had left); a --stats-interval series that would pass
# --memory-budget stops the run (exit 2, naming --stats-interval and --memory-budget, nothing
# written) instead of growing past it; an interval as long as the longest run (1e7 s) is one
# interval, not "more than 1000000"; an interval of 1 ps (0.001ns) stops at 1,000,000 intervals,
# and `1ps` is refused, as docs/cli.md says (units ns, us, ms, s); the per-pixel latency figures
# are held from the budget before the run, and so are an animation's frame records and their
# JSON, in torusrt-sim and torusrt-render (refused before the first frame when they cannot fit),
# and torusrt-render's --cost-image.
#
# Usage (CTest runs it so): bash tests/hostile/budget_needs.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim torusrt-render
command -v jq >/dev/null || { echo "$TEST_NAME: jq is not installed; skipped"; exit 77; }
time_limit 100
f=$(source_scene paper-image1) || exit 1
sim=("$BUILD/torusrt-sim" "$f" -q --ips 2x2)
cd "$TMP" || exit 1

# fails NAME STATUS PATTERN ARGS...: the run of $sim with ARGS exits STATUS, its stderr matches
# PATTERN (grep -E), and out/ stays empty.
fails() {
    local name=$1 status=$2 pattern=$3
    shift 3
    local err="./$name.err"
    rm -rf out && mkdir out
    "${run_limited[@]}" "${sim[@]}" "$@" >/dev/null 2>"$err" </dev/null
    local rc=$?
    check "$name: exit $rc, expected $status: $(head -c 300 "$err")" [ "$rc" -eq "$status" ]
    check "$name: the message ($(head -c 400 "$err"))" grep -qE -e "$pattern" "$err"
    check "$name: nothing written: $(ls -A out | tr '\n' ' ')" [ -z "$(ls -A out)" ]
}

# ---- the packets a frame needs -----------------------------------------------------------------
# The primaries that enter the space, from a run without a budget: all of them are made as the
# frame is set up, so a budget too small for them names that many.
"${run_limited[@]}" "${sim[@]}" --size 256x256 -o whole.png --stats whole.json --memory-budget 0 </dev/null
check "256x256 without a budget: exit $?" [ -s whole.json ]
entering=$(jq '65536 - .packets.primary_missed' whole.json)
fails "frame set up" 1 "memory budget exceeded: the outstanding packets \($entering of [0-9]+ bytes each\)" \
    --size 256x256 -o out/f%d.png --frames 3 --orbit 30 --memory-budget 18000K
fails "image set up" 1 "memory budget exceeded: the outstanding packets \($entering of [0-9]+ bytes each\)" \
    --size 256x256 -o out/i.png --t1 1 --memory-budget 12000K

# ---- the series inside the budget --------------------------------------------------------------
fails "series over the budget" 2 \
    "^torusrt-sim: --stats-interval 1.05e-06 s: memory budget exceeded: the series reached [0-9]+ intervals .* --memory-budget" \
    --size 16x16 -o out/m.png --stats out/m.json --stats-interval 1.05e-6 --memory-budget 8M
check "series over the budget: one line" [ "$(wc -l <"series over the budget.err")" -eq 1 ]
# The same series fits a larger budget, and then holds every interval.
"${run_limited[@]}" "${sim[@]}" --size 16x16 -o m.png --stats m.json --stats-interval 1e-4 --memory-budget 8M </dev/null
check "a series within the budget: exit $?" [ -s m.series.csv ]
rows=$(($(wc -l <m.series.csv) - 1))
expected=$(jq '(.sim_time_s / 1e-4) | ceil' m.json)
check "a series within the budget: $rows intervals, the run's $expected" [ "$rows" -eq "$expected" ]

# ---- the interval's bounds ---------------------------------------------------------------------
"${run_limited[@]}" "${sim[@]}" --size 16x16 -o l.png --stats l.json --stats-interval 1e7 >/dev/null 2>long.err </dev/null
check "--stats-interval 1e7: exit $?: $(head -c 300 long.err)" [ -s l.series.csv ]
check "--stats-interval 1e7: one interval" [ "$(wc -l <l.series.csv 2>/dev/null)" -eq 2 ]
check "--stats-interval 1e7: it ends at the image time" \
    [ "$(cut -d, -f2 l.series.csv 2>/dev/null | tail -n 1 | awk '{printf "%.6f", $1}')" = \
      "$(jq '.sim_time_s' l.json | awk '{printf "%.6f", $1}')" ]
fails "--stats-interval 0.001ns" 2 \
    "^torusrt-sim: --stats-interval 1e-12 s: the run needs more than 1000000 intervals \(it passed 1e-06 s simulated" \
    --size 16x16 -o out/p.png --stats out/p.json --stats-interval 0.001ns
fails "--stats-interval 1ps" 2 "^torusrt-sim: --stats-interval '1ps': expected a time: .* unit ns, us, ms or s" \
    --size 16x16 -o out/p.png --stats out/p.json --stats-interval 1ps

# ---- the per-pixel latency figures inside the budget -------------------------------------------
# 2048x2048: the frame buffer and the image (about 120 MiB) fit 150M, the latency figures' 16
# bytes a pixel (64 MiB) do not; refused before any run, naming them.
fails "per-pixel latency" 1 \
    "memory budget exceeded: the per-pixel latency figures of 2048x2048 pixels would take 64.0 MiB" \
    --size 2048x2048 -o out/big.png --stats out/big.json --memory-budget 150M

# ---- an animation's frame records inside the budget --------------------------------------------
# 20000 frames of 1x1 with --stats: their records and JSON do not fit 8M; refused before the
# first frame, naming them (the run took 162 MB when they were not counted).
fails "frame records" 1 "memory budget exceeded: the records of 20000 frames and their JSON" \
    --size 1x1 -o 'out/f%d.png' --frames 20000 --orbit 360 --memory-budget 8M --stats out/f.json
# 100 frames fit, and every record is in the JSON.
"${run_limited[@]}" "${sim[@]}" --size 1x1 -o 'r%d.png' --frames 100 --orbit 360 --memory-budget 8M \
    --stats r.json </dev/null
check "100 frames in 8M: exit $?, 100 records" [ "$(jq '.frames | length' r.json)" = 100 ]
# The same in torusrt-render (it took 396 MB for 40000 frames when they were not counted), with
# and without --stats.
render=("$BUILD/torusrt-render" "$f" -q)
rm -rf out && mkdir out
"${run_limited[@]}" "${render[@]}" --size 1x1 -o 'out/f%d.png' --frames 20000 --orbit 360 --memory-budget 8M \
    --stats out/f.json >/dev/null 2>render.err </dev/null
rc=$?
check "render frame records: exit $rc, expected 1: $(head -c 300 render.err)" [ "$rc" -eq 1 ]
check "render frame records: the message: $(head -c 300 render.err)" \
    grep -q "^torusrt-render: memory budget exceeded: the records of 20000 frames and their JSON" render.err
check "render frame records: nothing written: $(ls -A out | head -c 100)" [ -z "$(ls -A out)" ]
"${run_limited[@]}" "${render[@]}" --size 1x1 -o 'out/f%d.png' --frames 20000 --orbit 360 --memory-budget 8M \
    >/dev/null 2>render.err </dev/null
rc=$?
check "render frame records without --stats: exit $rc, expected 1" [ "$rc" -eq 1 ]
check "render frame records without --stats: the message: $(head -c 300 render.err)" \
    grep -q "^torusrt-render: memory budget exceeded: the records of 20000 frames would take" render.err
"${run_limited[@]}" "${render[@]}" --size 1x1 -o 'rr%d.png' --frames 100 --orbit 360 --memory-budget 8M \
    --stats rr.json </dev/null
check "render: 100 frames in 8M: exit $?, 100 records" [ "$(jq '.frames | length' rr.json)" = 100 ]
# torusrt-render's --cost-image (8 bytes a pixel and its picture's canvas) is held from the
# budget too: 1000x1000 fits in 30M (a 27 MB frame buffer), with the cost image it does not.
rm -rf out && mkdir out
"${run_limited[@]}" "${render[@]}" --size 1000x1000 -o out/c.png --cost-image out/cost.png --memory-budget 30M \
    >/dev/null 2>cost.err </dev/null
rc=$?
check "render --cost-image past the budget: exit $rc, expected 1: $(head -c 300 cost.err)" [ "$rc" -eq 1 ]
check "render --cost-image past the budget: the message: $(head -c 300 cost.err)" \
    grep -q "^torusrt-render: memory budget exceeded: the --cost-image of 1000x1000 pixels" cost.err
check "render --cost-image past the budget: nothing written: $(ls -A out | head -c 100)" [ -z "$(ls -A out)" ]
"${run_limited[@]}" "${render[@]}" --size 1000x1000 -o out/c.png --memory-budget 30M </dev/null
check "render 1000x1000 in 30M without --cost-image: exit $?" [ -s out/c.png ]

finish
