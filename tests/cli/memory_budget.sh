#!/usr/bin/env bash
# memory_budget.sh - small inputs that would take huge memory fail before allocating, in both
# executables: a 16384 x 16384 frame buffer (default 4G budget), 2000 spheres at one point
# (every one in every cell: 221 MB of cell lists, budget 16M), and a glass scene with
# --min-weight 0 --max-depth 1000 (the packets multiply without end, budget 2M). Each must
# exit 1 naming what exceeded the budget, and leave no output file; a bad size exits 2. The
# model's cost and scatter pilots and mapping tables, and the primaries made before the
# simulation starts, are checked the same way.
#
# Usage (CTest runs it so): bash tests/cli/memory_budget.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-render torusrt-sim
time_limit 120
tir=$(source_scene tir) || exit 1

view='v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1'
printf '%s resolution 16384 16384\nl 1 1 5\ns 0 0 0 1\n' "$view" >"$TMP/huge-image.nff"
{
    printf '%s resolution 8 8\nl 1 1 5\nf 1 1 1 1 0 0 0 1\n' "$view"
    for _ in $(seq 2000); do echo "s 0 0 0 1"; done
} >"$TMP/one-point.nff"

# expect_over NAME EXE PATTERN ARGS...: exit 1, stderr names the budget and PATTERN, no output.
expect_over() {
    local name=$1 exe=$2 pattern=$3
    shift 3
    local out="$TMP/out_$name"
    mkdir -p "$out"
    "${run_limited[@]}" "$BUILD/$exe" "$@" -o "$out/img.png" --stats "$out/s.json" -q \
        >"$TMP/$name.stdout" 2>"$TMP/$name.stderr" </dev/null
    local rc=$?
    check "$name: exit status $rc, expected 1 ($(head -c 300 "$TMP/$name.stderr"))" [ "$rc" -eq 1 ]
    check "$name: no 'memory budget exceeded: $pattern' on stderr: $(head -c 300 "$TMP/$name.stderr")" \
        grep -q "memory budget exceeded: .*$pattern" "$TMP/$name.stderr"
    check "$name: left files behind: $(ls "$out")" [ -z "$(ls -A "$out")" ]
}

for exe in torusrt-render torusrt-sim; do
    sim_args=()
    [ "$exe" = torusrt-sim ] && sim_args=(--t1 1 --ips 2)
    expect_over "$exe-frame-buffer" "$exe" "frame buffer of 16384x16384" "$TMP/huge-image.nff" "${sim_args[@]}"
    expect_over "$exe-cell-lists" "$exe" "cell lists" "$TMP/one-point.nff" --memory-budget 16M "${sim_args[@]}"
    expect_over "$exe-packets" "$exe" "packets" "$tir" --memory-budget 2M --min-weight 0 --max-depth 1000 \
        --size 8x8 "${sim_args[@]}"
    # Within budget the same runs work; a malformed size is a command-line error.
    "${run_limited[@]}" "$BUILD/$exe" "$TMP/one-point.nff" -o "$TMP/$exe-ok.png" -q --memory-budget 512M \
        "${sim_args[@]}" >/dev/null 2>"$TMP/$exe-ok.stderr"
    check "$exe: 2000 spheres within a 512M budget failed: $(head -c 300 "$TMP/$exe-ok.stderr")" [ -s "$TMP/$exe-ok.png" ]
    "${run_limited[@]}" "$BUILD/$exe" "$tir" -o "$TMP/$exe-nolimit.png" -q --memory-budget 0 --size 8x8 \
        "${sim_args[@]}" >/dev/null 2>&1
    check "$exe: --memory-budget 0 (no limit) failed" [ -s "$TMP/$exe-nolimit.png" ]
    "$BUILD/$exe" "$tir" -o "$TMP/$exe-bad.png" -q --memory-budget 4Q >/dev/null 2>"$TMP/$exe-bad.stderr"
    rc=$?
    check "$exe: --memory-budget 4Q gave exit $rc, expected 2" [ "$rc" -eq 2 ]
    check "$exe: --memory-budget 4Q message does not name the option" grep -q -- "--memory-budget" "$TMP/$exe-bad.stderr"
done

# The model's pilot and mapping tables are checked before they are made (under a 2 GB address
# space, so that a run that is not checked fails instead of taking the machine's memory): a pilot
# of 8000x8000 pixels in 100M, and the pilot and Scotch graph of 256^3 cells in 300M.
paper1=$(source_scene paper-image1) || exit 1
expect_over_limited() {
    (ulimit -v 2000000 && expect_over "$@" && echo "$PASSED $FAILED" >"$TMP/counts")
    read -r PASSED FAILED <"$TMP/counts"
}
for map in cost scatter; do
    expect_over_limited "pilot-$map" torusrt-sim "the pilot of 8000x8000 pixels" "$paper1" --size 8x8 --t1 1 \
        --ips 4 --map $map --pilot-size 8000x8000 --memory-budget 100M
    check "pilot-$map: the message names --map $map" grep -q -- "--map $map: memory budget" "$TMP/pilot-$map.stderr"
done
# Without a budget, a pilot the address space cannot hold fails with the run's out-of-memory
# message, naming the pilot of its mapping and --memory-budget.
for map in cost scatter; do
    (ulimit -v 800000 && "$BUILD/torusrt-sim" "$paper1" --size 8x8 --t1 1 --ips 4 --map $map \
        --pilot-size 8000x8000 --memory-budget 0 -q -o "$TMP/nomem.png" >/dev/null 2>"$TMP/nomem-$map.stderr")
    rc=$?
    check "pilot-$map without a budget: exit 1 (got $rc)" [ $rc = 1 ]
    check "pilot-$map without a budget: names --map $map ($(head -c 200 "$TMP/nomem-$map.stderr"))" \
        grep -q -- "^torusrt-sim: out of memory while running the pilot of --map $map: .*--memory-budget" \
        "$TMP/nomem-$map.stderr"
done
expect_over_limited cells-cost torusrt-sim "cells" "$paper1" --size 4x4 --t1 1 --ips 4 --map cost --cells 256 \
    --memory-budget 300M

# The packets made before the simulation starts (the primaries) are counted at the size the
# budget's limit uses: the message's figures agree with each other.
expect_over early-packets torusrt-sim "outstanding packets" "$paper1" --size 512x512 --t1 1 --ips 2 \
    --memory-budget 12M
check "early-packets: the packets' bytes exceed what is left ($(head -c 300 "$TMP/early-packets.stderr"))" \
    bash -c "! grep -q ', 0 bytes more than' '$TMP/early-packets.stderr'"
finish
