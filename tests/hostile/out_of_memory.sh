#!/usr/bin/env bash
# out_of_memory.sh - the system refusing memory (ulimit -v) while a 4096-node machine is being
# built: the run says what it was building and names --memory-budget, exits 1 (no abort), and
# leaves no output and no temporary (its VCD's and save file's, and the trace's FIFO folder).
#
# Usage (CTest runs it so): bash tests/hostile/out_of_memory.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
time_limit 60
f=$(source_scene paper-image1) || exit 1
cd "$TMP" || exit 1
mkdir out tmpdir
# 150 MB of address space: the scene loads, the machine's 4096 nodes do not fit.
(TMPDIR="$TMP/tmpdir" "${run_limited[@]}" bash -c 'ulimit -v 150000 && exec "$@"' _ "$BUILD/torusrt-sim" "$f" -q --t1 1 --ips 16x16x16 \
    --size 8x8 -o out/a.png --stats out/a.json --vcd out/a.vcd >/dev/null 2>err.txt </dev/null)
rc=$?
check "4096 nodes under ulimit -v: exit $rc, expected 1: $(head -c 300 err.txt)" [ "$rc" -eq 1 ]
check "4096 nodes under ulimit -v: the message names the stage: $(head -c 300 err.txt)" \
    grep -q "^torusrt-sim: out of memory while building the machine (4096 nodes)" err.txt
check "4096 nodes under ulimit -v: the message names --memory-budget" grep -q -- "--memory-budget" err.txt
check "4096 nodes under ulimit -v: no abort message" bash -c '! grep -q "terminate called" err.txt'
check "4096 nodes under ulimit -v: nothing left: $(ls -A out; ls -A tmpdir)" \
    [ -z "$(ls -A out)$(ls -A tmpdir)" ]
finish
