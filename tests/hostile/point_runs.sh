#!/usr/bin/env bash
# point_runs.sh - the files a sweep and compare-mappings give each point's run: an output option
# that every point would share among the fixed options (--stats-series, -o, --vcd, --frames-csv)
# refused before --out is made, naming the option.
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

finish
