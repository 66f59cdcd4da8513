#!/usr/bin/env bash
# experiments/sweep: a 2 x 2 sweep (two axes, small scene, 16x16) writes one CSV row per point with
# the axis columns, the status and the chosen JSON fields, whose values are those of the points'
# own JSON reports, and a PNG plot; a point that fails is listed and makes the exit status 1
# while the other points still get their rows; a malformed --axis is a command-line error (2).
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
for tool in parallel gnuplot python3 jq; do
    command -v $tool >/dev/null || { fail "$tool not installed"; finish; exit 1; }
done
SWEEP=$SRC/experiments/sweep
scene=$SRC/scenes/paper-image2.nff
ispng() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; }
# same A B: the CSV's A is the JSON's B to 6 significant digits (the CSV rounds to 6).
same() { python3 -c 'import sys; a, b = sys.argv[1:]; sys.exit(not (a and b and a == "%.6g" % float(b)))' "$1" "$2"; }
# col CSV ROW COLUMN: the value in data row ROW (1 = first) of the column named COLUMN.
col() { awk -F, -v r="$2" -v c="$3" 'NR == 1 { for (i = 1; i <= NF; i++) ix[$i] = i; next } NR == r + 1 { print $ix[c] }' "$1"; }

TORUSRT_BUILD=$BUILD "$SWEEP" "$scene" --axis ips=1,2x2 --axis map=block,cyclic --out "$TMP/s" -j 2 \
    --columns sim_time_s,efficiency_busy,links.utilisation.mean,packets.created.total -- --size 16x16 --t1 1 \
    >"$TMP/out1" 2>"$TMP/err"
rc=$?
check "2 x 2 sweep exits 0 (got $rc: $(tail -n 2 "$TMP/err" | tr '\n' ' '))" test "$rc" -eq 0
csv=$TMP/s/sweep.csv
check "CSV header: axes, status, chosen fields" \
    test "$(head -n 1 "$csv")" = "ips,map,status,sim_time_s,efficiency_busy,links.utilisation.mean,packets.created.total"
check "CSV has 4 rows" test "$(awk 'NR > 1' "$csv" | wc -l)" -eq 4
check "rows are the cartesian product, first axis slowest" \
    test "$(awk -F, 'NR > 1 { printf "%s/%s ", $1, $2 }' "$csv")" = "1/block 1/cyclic 2x2/block 2x2/cyclic "
check "every point ok" test "$(awk -F, 'NR > 1 && $3 != "ok"' "$csv" | wc -l)" -eq 0
for row in 1 2 3 4; do
    ips=$(col "$csv" $row ips) map=$(col "$csv" $row map)
    json=$TMP/s/points/ips_$ips-map_$map.json
    check "row $row: sim_time_s is the point's JSON value" \
        same "$(col "$csv" $row sim_time_s)" "$(jq -r .sim_time_s "$json")"
    check "row $row: a nested field by dotted name" \
        same "$(col "$csv" $row links.utilisation.mean)" "$(jq -r .links.utilisation.mean "$json")"
    check "row $row: the axis value reached the run" test "$(jq -r .config.mapping "$json")" = "$map"
done
check "one IP: no link traffic" same "$(col "$csv" 1 links.utilisation.mean)" 0
check "2x2 cyclic is faster than one IP" \
    awk -v a="$(col "$csv" 4 sim_time_s)" -v b="$(col "$csv" 1 sim_time_s)" 'BEGIN { exit !(a + 0 < b + 0) }'
check "the plot is a PNG" ispng "$TMP/s/sweep.png"

TORUSRT_BUILD=$BUILD "$SWEEP" "$scene" --axis map=block,nonsense --out "$TMP/f" -j 2 -- --size 16x16 --t1 1 \
    >"$TMP/out" 2>"$TMP/err"
rc=$?
check "a failing point makes the sweep exit 1 (got $rc)" test "$rc" -eq 1
check "the failed point is listed with its message" grep -q "FAILED point map_nonsense.*--map 'nonsense'" "$TMP/err"
check "the failed point is a 'failed' row" test "$(col "$TMP/f/sweep.csv" 2 status)" = failed
check "the other point is ok" test "$(col "$TMP/f/sweep.csv" 1 status)" = ok

check "progress: one [k/N] line per point" test "$(grep -c '^sweep: \[[1-4]/4\] ips_.*: ok$' "$TMP/out1")" -eq 4
check "CSV values have at most 6 significant digits" \
    python3 -c 'import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
sys.exit(not all(len(v.lstrip("-").replace(".", "").lstrip("0").split("e")[0]) <= 6
                 for r in rows for k, v in r.items() if k not in ("ips", "map", "status") and v))' "$csv"

TORUSRT_BUILD=$BUILD "$SWEEP" "$scene" --axis queue=1,0 --out "$TMP/d" -j 2 --y efficiency \
    -- --size 16x16 --t1 1 --flow none --ips 2x2 >"$TMP/out" 2>"$TMP/err"
rc=$?
check "a deadlocked point is a result, not a failure (exit $rc)" test "$rc" -eq 0
check "the deadlocked point has its own status" test "$(col "$TMP/d/sweep.csv" 1 status)" = deadlock
check "the deadlocked point keeps the JSON's figures (sim_time_s = the stall's time)" \
    same "$(col "$TMP/d/sweep.csv" 1 sim_time_s)" "$(jq -r .deadlock.time_s "$TMP/d/points/queue_1.json")"
check "the deadlock is listed" grep -q "point queue_1 deadlocked at" "$TMP/err"
check "no temporaries left" test -z "$(find "$TMP/d" "$TMP/f" -name '*.tmp')"
check "--y efficiency: the plotted field is a CSV column" \
    test "$(head -n 1 "$TMP/d/sweep.csv" | tr ',' '\n' | grep -cx efficiency)" -eq 1
check "--y efficiency: the ok point's efficiency" \
    same "$(col "$TMP/d/sweep.csv" 2 efficiency)" "$(jq -r .efficiency "$TMP/d/points/queue_0.json")"
check "--y efficiency: the plot is a PNG" ispng "$TMP/d/sweep.png"

TORUSRT_BUILD=$BUILD "$SWEEP" "$scene" --axis ipss=1,2 --out "$TMP/m" -- --size 16x16 >/dev/null 2>"$TMP/err"
rc=$?
check "a misspelt axis: exit 2 before any point runs (got $rc)" test "$rc" -eq 2
check "a misspelt axis: torusrt-sim's message" grep -q -- "--ipss" "$TMP/err"
check "a misspelt axis: no point was run" test ! -d "$TMP/m/points"

TORUSRT_BUILD=$BUILD "$SWEEP" "$scene" --axis ips --out "$TMP/b" >/dev/null 2>"$TMP/err"
rc=$?
check "malformed --axis: exit 2 (got $rc)" test "$rc" -eq 2
check "malformed --axis: the message names it" grep -q -- "--axis 'ips'" "$TMP/err"
finish
