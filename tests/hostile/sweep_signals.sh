#!/usr/bin/env bash
# sweep_signals.sh - TERM or HUP sent to the sweep's shell alone (not to its process group) while
# its points run stops the backend and the points too: the sweep says so and ends with 128 + the
# signal's number, and no process of its --out folder runs on. A study's script (set -e) waiting
# in lib.sh's in_child does the same for every stopping signal, and so it does between its runs.
#
# Usage (CTest runs it so): bash tests/hostile/sweep_signals.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
for tool in python3 parallel gnuplot jq pgrep; do
    command -v "$tool" >/dev/null || { echo "$TEST_NAME: $tool is not installed; skipped"; exit 77; }
done
EXP=$SRC/experiments
export TORUSRT_BUILD=$BUILD
scene1=$(source_scene paper-image1) || exit 1
cd "$TMP" || exit 1
cp "$scene1" s.nff
for sig in TERM HUP; do
    out=$TMP/sw$sig
    # Points of some seconds each, so that the signal comes while one runs.
    "$EXP/sweep" --build "$BUILD" s.nff --axis ips=4x4,2x2,1 --out "$out" -- --size 1200x1200 \
        >/dev/null 2>"err$sig.txt" </dev/null &
    sweep=$!
    for _ in $(seq 300); do pgrep -f "$out/points" >/dev/null && break; sleep 0.1; done
    check "sweep $sig: a point started" pgrep -f "$out/points" >/dev/null
    kill -s "$sig" "$sweep"
    wait "$sweep"
    rc=$?
    code=$((128 + $(kill -l "$sig")))
    check "sweep $sig: exit $rc, expected $code" [ "$rc" -eq "$code" ]
    check "sweep $sig: the message: $(head -c 200 "err$sig.txt")" grep -q "sweep: stopped by SIG$sig; the same command runs the points not done" "err$sig.txt"
    for _ in $(seq 50); do pgrep -f "$out" >/dev/null || break; sleep 0.1; done
    left=$(pgrep -f "$out" | tr '\n' ' ')
    check "sweep $sig: processes left running: $left" [ -z "$left" ]
    for pid in $left; do kill "$pid" 2>/dev/null; done
done
# A study's way of running its points: under set -euo pipefail, through lib.sh's in_child.
printf '%s\n' '#!/usr/bin/env bash' 'set -euo pipefail' "source '$EXP/lib.sh'" 'in_child sleep 30' >study.sh
for sig in TERM HUP INT QUIT USR1 USR2 ALRM; do
    env --default-signal=INT,QUIT bash study.sh 2>"study$sig.txt" </dev/null &  # not ignoring INT, QUIT as a background job would
    study=$!
    for _ in $(seq 100); do pgrep -P "$study" sleep >/dev/null && break; sleep 0.1; done
    child=$(pgrep -P "$study" sleep)
    kill -s "$sig" "$study"
    wait "$study"
    rc=$?
    code=$((128 + $(kill -l "$sig")))
    check "study $sig: exit $rc, expected $code" [ "$rc" -eq "$code" ]
    check "study $sig: the message: $(head -c 200 "study$sig.txt")" \
        grep -q "study.sh: stopped by SIG$sig; the same command runs the points not done" "study$sig.txt"
    check "study $sig: its child stopped" bash -c "! kill -0 $child 2>/dev/null"
done
# The same between its runs: the signal comes while a command of its own runs in the foreground.
printf '%s\n' '#!/usr/bin/env bash' 'set -euo pipefail' "source '$EXP/lib.sh'" 'sleep 2' 'touch never' \
    'in_child sleep 30' >between.sh
for sig in TERM USR1; do
    env --default-signal=INT,QUIT bash between.sh 2>"between$sig.txt" </dev/null &
    study=$!
    for _ in $(seq 100); do pgrep -P "$study" sleep >/dev/null && break; sleep 0.1; done
    kill -s "$sig" "$study"
    wait "$study"
    rc=$?
    code=$((128 + $(kill -l "$sig")))
    check "between runs, $sig: exit $rc, expected $code" [ "$rc" -eq "$code" ]
    check "between runs, $sig: the message: $(head -c 200 "between$sig.txt")" \
        grep -q "between.sh: stopped by SIG$sig" "between$sig.txt"
    check "between runs, $sig: nothing after the signal ran" [ ! -e never ]
done
finish
