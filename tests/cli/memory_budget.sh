#!/usr/bin/env bash
# memory_budget.sh - small inputs that would take huge memory fail before allocating, in both
# executables: a 16384 x 16384 frame buffer (default 4G budget), 2000 spheres at one point
# (every one in every cell: 221 MB of cell lists, budget 16M), and a glass scene with
# --min-weight 0 --max-depth 1000 (the packets multiply without end, budget 2M). Each must
# exit 1 naming what exceeded the budget, and leave no output file; a bad size exits 2.
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
finish
