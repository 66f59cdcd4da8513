#!/usr/bin/env bash
# point_runs.sh - the files a sweep, compare-mappings and run_point.sh give each point's run:
# an output option that every point would share among the fixed options (--stats-series, -o,
# --vcd, --frames-csv) refused before --out is made, naming the option; a series
# (--stats-interval without --stats-series) named after the point, with no temporary left;
# run_point.sh refusing a command that gives -o or --stats, or whose output option names the
# point's own JSON, image, log or series, with nothing written; and --t1-from naming a FIFO,
# /dev/zero, a folder or a file over 64 MiB refused at once, naming --t1-from.
#
# Usage (CTest runs it so): bash tests/hostile/point_runs.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
for tool in python3 parallel gnuplot jq; do
    command -v "$tool" >/dev/null || { echo "$TEST_NAME: $tool is not installed; skipped"; exit 77; }
done
time_limit 100
EXP=$SRC/experiments
export TORUSRT_BUILD=$BUILD
scene=$(source_scene paper-image1) || exit 1
cd "$TMP" || exit 1
cp "$scene" s.nff
sim=$BUILD/torusrt-sim
small=(--size 8x8)

# refused NAME PATTERN COMMAND...: exit 2, stderr matching PATTERN (grep -e).
refused() {
    local name=$1 pattern=$2
    shift 2
    local log
    log=./$(printf '%s' "$name" | tr -c 'A-Za-z0-9._-' '_')
    "${run_limited[@]}" "$@" >"$log.out" 2>"$log.err" </dev/null
    local rc=$?
    check "$name: exit $rc, expected 2: $(head -c 300 "$log.err")" [ "$rc" -eq 2 ]
    check "$name: the message names it ('$pattern'): $(head -c 300 "$log.err")" grep -q -e "$pattern" "$log.err"
}
# temporaries DIR: the names under DIR that look like a temporary (*.tmp*, .NAME.XXXXXX).
temporaries() { find "$1" \( -name '*.tmp*' -o -name '.*.??????' \) -print 2>/dev/null; }

# ---- shared outputs among the fixed options ----------------------------------------------------
sweep=("$EXP/sweep" --build "$BUILD")
refused "sweep: --stats-series fixed" "^sweep: --stats-series among the fixed options" \
    "${sweep[@]}" s.nff --axis ips=1,2 --out sw-series -- "${small[@]}" --stats-interval 0.1 --stats-series "$TMP/ser.csv"
check "sweep: --stats-series fixed: --out not made" [ ! -e sw-series ]
check "sweep: --stats-series fixed: no series written" [ ! -e ser.csv ]
for opt in -o --vcd --frames-csv --stats; do
    refused "sweep: $opt fixed" "^sweep: $opt among the fixed options" \
        "${sweep[@]}" s.nff --axis ips=1,2 --out "sw$opt" -- "${small[@]}" "$opt" "$TMP/shared$opt"
    check "sweep: $opt fixed: --out not made" [ ! -e "sw$opt" ]
done
refused "sweep: --stats-series=FILE fixed" "^sweep: --stats-series among the fixed options" \
    "${sweep[@]}" s.nff --axis ips=1,2 --out sw-eq -- "${small[@]}" --stats-interval 0.1 --stats-series="$TMP/ser.csv"
check "sweep: --stats-series=FILE fixed: --out not made" [ ! -e sw-eq ]
refused "compare-mappings: --stats-series after --" "--stats-series after --: every run would write it" \
    "$EXP/compare-mappings" --build "$BUILD" --map block,cyclic s.nff --out cm.png -- --ips 2 "${small[@]}" \
    --stats-interval 0.1 --stats-series "$TMP/ser.csv"
check "compare-mappings: --stats-series after --: nothing written" [ ! -e ser.csv ] && [ ! -e cm.png ]

# ---- a series under the tools ------------------------------------------------------------------
"${run_limited[@]}" "${sweep[@]}" s.nff --axis ips=1,2 --out sws -- "${small[@]}" --stats-interval 1e-4 \
    >sws.out 2>sws.err </dev/null
check "sweep with --stats-interval: exit $?: $(tail -c 300 sws.err)" [ -s sws/sweep.csv ]
for p in ips_1 ips_2; do
    check "sweep with --stats-interval: $p's series named after the point" [ -s "sws/points/$p.series.csv" ]
    check "sweep with --stats-interval: $p's series is a CSV" grep -q '^start_s,end_s,' "sws/points/$p.series.csv"
done
check "sweep with --stats-interval: no temporary left: $(temporaries sws | head -3)" [ -z "$(temporaries sws)" ]
"${run_limited[@]}" "${sweep[@]}" s.nff --axis ips=1,2 --out sws -- "${small[@]}" --stats-interval 1e-4 \
    >sws2.out 2>sws2.err </dev/null
check "sweep with --stats-interval again: both points done before" grep -q "(2 done before)" sws2.out

mkdir rp
"${run_limited[@]}" "$EXP/run_point.sh" rp/s.json -- "$sim" s.nff "${small[@]}" --t1 1 --stats-interval 1e-4 \
    >rp-s.out 2>rp-s.err </dev/null
check "run_point with --stats-interval: exit $?: $(head -c 300 rp-s.err)" [ -s rp/s.json ]
check "run_point with --stats-interval: the series named after the point" grep -q '^start_s,' rp/s.series.csv
check "run_point with --stats-interval: no temporary left: $(temporaries rp | head -3)" [ -z "$(temporaries rp)" ]
"${run_limited[@]}" "$EXP/run_point.sh" rp/e.json -- "$sim" s.nff "${small[@]}" --t1 1 --stats-interval=1e-4 \
    --stats-series rp/mine.csv >rp-e.out 2>rp-e.err </dev/null
check "run_point with its own --stats-series: exit $?: $(head -c 300 rp-e.err)" [ -s rp/mine.csv ]
check "run_point with its own --stats-series: no series of its own" [ ! -e rp/e.series.csv ]

# ---- run_point.sh: the command's outputs against the point's own files -------------------------
for case in "--vcd rp/g.log" "--stats-series rp/g.json" "--frames-csv rp/g.png" "--write-map rp/g.series.csv"; do
    read -r opt file <<<"$case"
    refused "run_point: $opt its own $file" "$opt '$file': is the point's own file" \
        "$EXP/run_point.sh" rp/g.json -- "$sim" s.nff "${small[@]}" --t1 1 --stats-interval 1e-4 "$opt" "$file"
    check "run_point: $opt its own $file: nothing written: $(ls rp | grep '^g\.' | tr '\n' ' ')" \
        [ -z "$(ls rp | grep '^g\.')" ]
done
refused "run_point: --vcd=its own log" "--vcd 'rp/../rp/g.log': is the point's own file" \
    "$EXP/run_point.sh" rp/g.json -- "$sim" s.nff "${small[@]}" --t1 1 --vcd=rp/../rp/g.log
refused "run_point: --vcd whose save file is the point's JSON" "its GTKWave save file rp/z.gtkw is the point's own file" \
    "$EXP/run_point.sh" rp/z.gtkw -- "$sim" s.nff "${small[@]}" --t1 1 --vcd rp/z.vcd
check "run_point: --vcd whose save file is the point's JSON: nothing written" [ ! -e rp/z.gtkw ] && [ ! -e rp/z.vcd ]
printf 'kept\n' >rp/h.log
refused "run_point: --vcd its own existing log" "--vcd 'rp/h.log'" \
    "$EXP/run_point.sh" rp/h.json -- "$sim" s.nff "${small[@]}" --t1 1 --vcd rp/h.log
check "run_point: --vcd its own existing log: the log kept" grep -qx kept rp/h.log
for opt in -o --stats; do
    refused "run_point: the command gives $opt" "$opt 'rp/other': run_point.sh gives each point's -o and --stats" \
        "$EXP/run_point.sh" rp/i.json -- "$sim" s.nff "${small[@]}" --t1 1 "$opt" rp/other
    check "run_point: the command gives $opt: nothing written" [ ! -e rp/other ] && [ ! -e rp/i.json ]
done

# ---- run_point.sh --t1-from: only a regular file, of a point's size -----------------------------
mkfifo ff
mkdir t1dir
truncate -s 65M big.json
for case in "ff:a FIFO" "/dev/zero:a device" "t1dir:a folder" "big.json:over 64 MiB"; do
    file=${case%%:*} what=${case#*:}
    refused "run_point --t1-from $what" "^run_point: --t1-from '$file'" \
        "$EXP/run_point.sh" rp/t.json --t1-from "$file" -- "$sim" s.nff "${small[@]}"
    check "run_point --t1-from $what: no point written" [ ! -e rp/t.json ]
done

finish
