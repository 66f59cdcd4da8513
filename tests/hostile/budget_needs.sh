#!/usr/bin/env bash
# budget_needs.sh - what the memory budget's messages count: the packets a frame needs as it is
# set up are all of its primaries entering the space (not one more than the budget had left).
#
# Usage (CTest runs it so): bash tests/hostile/budget_needs.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
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

finish
