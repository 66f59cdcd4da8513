#!/usr/bin/env bash
# python_tracebacks.sh - the Python tools of experiments/ end with a message, never a traceback:
# - standard output closed (`>&-`): compare-mappings, report machine and the sweep say
#   `standard output: cannot write: Bad file descriptor`, exit 1, as torusrt-sim does;
# - compare-mappings stopped by Ctrl-C (SIGINT) while a run goes on: one line, exit 130;
# - compare-mappings on a scene whose name is not UTF-8, whose run fails: torusrt-sim's message
#   shown (the byte replaced), exit 1;
# - a CSV row with fewer fields than its header (a cut file): `report compare` names the file,
#   the line and the counts, exit 1;
# - report machine on a report whose config.option_order is not a list: named, exit 1.
#
# Usage (CTest runs it so): bash tests/hostile/python_tracebacks.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
for tool in python3 parallel gnuplot jq; do
    command -v "$tool" >/dev/null || { echo "$TEST_NAME: $tool is not installed; skipped"; exit 77; }
done
time_limit 60
EXP=$SRC/experiments
export TORUSRT_BUILD=$BUILD
scene1=$(source_scene paper-image1) || exit 1
cd "$TMP" || exit 1
cp "$scene1" s.nff
"$BUILD/torusrt-sim" s.nff -q -o a.png --size 8x8 --stats a.json </dev/null

# ends STATUS NAME PATTERN: the last command's status ($rc) and err.txt.
ends() {
    check "$2: exit $rc, expected $1: $(head -c 300 err.txt)" [ "$rc" -eq "$1" ]
    check "$2: the message ('$3'): $(head -c 300 err.txt)" grep -q -e "$3" err.txt
    check "$2: no traceback" test "$(grep -c 'Traceback\|Error:' err.txt)" -eq 0
}
cm=("$EXP/compare-mappings" --build "$BUILD" --map block,cyclic)

# ---- standard output closed --------------------------------------------------------------
"${run_limited[@]}" "${cm[@]}" s.nff --out c.png -- --ips 2 --size 8x8 >&- 2>err.txt </dev/null
rc=$?
ends 1 "cm >&-" "compare-mappings: standard output: cannot write: Bad file descriptor"
"${run_limited[@]}" python3 "$EXP/report" machine a.json >&- 2>err.txt </dev/null
rc=$?
ends 1 "report machine >&-" "report: standard output: cannot write: Bad file descriptor"
"${run_limited[@]}" "$EXP/sweep" --build "$BUILD" s.nff --axis ips=1 --out sw -- --size 8x8 >&- 2>err.txt </dev/null
rc=$?
ends 1 "sweep >&-" "sweep: standard output: cannot write: Bad file descriptor"

# ---- Ctrl-C while a run goes on ----------------------------------------------------------
timeout --preserve-status -s INT 2 "${cm[@]}" s.nff --out big.png -- --ips 4x4 --size 1200x1200 \
    >/dev/null 2>err.txt </dev/null
rc=$?
ends 130 "cm stopped by SIGINT" "compare-mappings: stopped by SIGINT"
check "cm stopped by SIGINT: no image" [ ! -e big.png ]

# ---- a scene name that is not UTF-8, its run failing ----------------------------------------
bad=$'\xffb.nff'
printf 's 0 0 0 1\n\001\n' >"$bad"
"${run_limited[@]}" "${cm[@]}" "$bad" --out c.png -- --ips 2 --size 8x8 >/dev/null 2>err.txt </dev/null
rc=$?
ends 1 "cm, a non-UTF-8 scene name" "compare-mappings: --map block failed (exit 1)"

# ---- a CSV row with fewer fields than the header --------------------------------------------
mkdir ca cb
printf 'scene,n,status,sim_time_s\na,1,ok,1\n' >ca/fig7.csv
printf 'scene,n,status,sim_time_s\na\n' >cb/fig7.csv
"${run_limited[@]}" python3 "$EXP/report" compare ca cb >/dev/null 2>err.txt </dev/null
rc=$?
ends 1 "report compare, a cut row" "cb/fig7.csv: line 2: 1 fields, the header has 4"

# ---- a report whose config.option_order is not a list ---------------------------------------
jq '.config.option_order = null' a.json >n.json
"${run_limited[@]}" python3 "$EXP/report" machine n.json >/dev/null 2>err.txt </dev/null
rc=$?
ends 1 "report machine, option_order null" "n.json: config.option_order: null, not a list of option names"
finish
