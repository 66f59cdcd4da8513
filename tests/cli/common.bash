# shellcheck shell=bash
# common.bash - shared helpers for the command-line tests (sourced, not run; not named *.sh, so
# CTest does not run it as a test).
# Usage: source "$(dirname "$0")/common.bash" "$@"
# Checks the two arguments (BUILD_DIR SOURCE_DIR) and sets BUILD, SRC, SCENE_DIR, TEST_NAME and
# TMP (a temporary folder, removed on exit), the pass/fail counters and the helpers below.
if [ $# -ne 2 ]; then
    echo "usage: bash $0 BUILD_DIR SOURCE_DIR" >&2
    exit 2
fi
BUILD=$(cd "$1" && pwd) || exit 2
SRC=$(cd "$2" && pwd) || exit 2
# The scenes of the tests that honour $TORUSRT_SCENE_DIR: that folder when set, else SOURCE_DIR/scenes.
# shellcheck disable=SC2034 # used by the scripts that source this file
SCENE_DIR=${TORUSRT_SCENE_DIR:-$SRC/scenes}
TEST_NAME=$(basename "$0" .sh)
TMP=$(mktemp -d "${TMPDIR:-/tmp}/$TEST_NAME.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT
PASSED=0
FAILED=0
run_limited=()

pass() { PASSED=$((PASSED + 1)); }
fail() { FAILED=$((FAILED + 1)); echo "FAIL: $*"; }
# check DESCRIPTION COMMAND...: passes if the command succeeds.
check() { local what=$1; shift; if "$@"; then pass; else fail "$what"; fi; }
# finish: the summary line; fails when a check failed, and when no check ran at all.
finish() {
    echo "$PASSED passed, $FAILED failed"
    if [ "$PASSED" -eq 0 ] && [ "$FAILED" -eq 0 ]; then echo "FAIL: $TEST_NAME ran no checks"; return 1; fi
    [ "$FAILED" -eq 0 ]
}
# sim_ok NAME ARGS...: a torusrt-sim run ($sim, set by the script) that must succeed, quiet, its
# stderr in $TMP/NAME.stderr.
sim_ok() {
    local name=$1
    shift
    if "${run_limited[@]}" "$sim" "$@" -q >/dev/null 2>"$TMP/$name.stderr" </dev/null; then pass; else
        fail "$name: torusrt-sim $* failed: $(head -c 300 "$TMP/$name.stderr")"
        return 1
    fi
}
# bad_option OPTION NAME ARGS...: a torusrt-sim run of $scene at ${size[@]} (set by the script)
# with ARGS must exit 2, name OPTION on stderr and write neither its frames nor its stats.
bad_option() {
    local option=$1 name=$2
    shift 2
    rm -rf "$TMP/bad" && mkdir "$TMP/bad"
    "${run_limited[@]}" "$sim" "$scene" "${size[@]}" -q "$@" -o "$TMP/bad/f_%d.png" --stats "$TMP/bad/s.json" \
        >/dev/null 2>"$TMP/bad.stderr" </dev/null
    local rc=$?
    check "$name: exit 2 (got $rc)" [ "$rc" = 2 ]
    check "$name: names $option ($(head -c 200 "$TMP/bad.stderr"))" grep -q -- "$option" "$TMP/bad.stderr"
    check "$name: no output" [ -z "$(ls "$TMP/bad")" ]
}
# json FILE FILTER: one value from a JSON file.
json() { jq -r "$2" "$1"; }

# json_get FILE a.b.c: the scalar at that path of torusrt's pretty-printed (2-space) JSON, read
# with awk (no jq needed), not through arrays; empty if absent.
json_get() {
    awk -v path="$2" '
        {
            match($0, /^ */); depth = RLENGTH / 2
            if (match($0, /^ *"[^"]*": /)) {
                key = substr($0, RSTART, RLENGTH); sub(/^ *"/, "", key); sub(/": $/, "", key)
                stack[depth] = key
                p = stack[1]; for (i = 2; i <= depth; i++) p = p "." stack[i]
                if (p == path) { v = substr($0, RSTART + RLENGTH); sub(/,$/, "", v); print v; exit }
            } else stack[depth] = "[]"
        }' "$1"
}

# need_exe NAME...: exits 1 (the test fails) unless every BUILD/NAME is an executable.
need_exe() {
    local exe
    for exe in "$@"; do
        if [ ! -x "$BUILD/$exe" ]; then
            echo "$TEST_NAME: $BUILD/$exe not found or not executable (build the $exe target)" >&2
            exit 1
        fi
    done
}

# time_limit SECONDS: sets run_limited, a command prefix that kills a hung run after SECONDS
# (a failure, not a stuck test run); left empty without coreutils' timeout.
time_limit() {
    run_limited=()
    if command -v timeout >/dev/null 2>&1; then run_limited=(timeout -k 5 "$1"); fi
}

# source_scene NAME: prints the path of SOURCE_DIR/scenes/NAME.nff, or writes NAME.nff into
# $TMP with torusrt-genscenes when the source tree lacks it; returns 1 with a message when
# neither works. Use: f=$(source_scene NAME) || exit 1
source_scene() {
    local f="$SRC/scenes/$1.nff" gen="$BUILD/torusrt-genscenes"
    if [ -f "$f" ]; then
        echo "$f"
    elif [ -x "$gen" ] && "$gen" "$TMP" "$1" >/dev/null; then
        echo "$TMP/$1.nff"
    else
        echo "$TEST_NAME: no $f and cannot generate it with $gen" >&2
        return 1
    fi
}

# render_ok NAME SCENE OUT ARGS...: torusrt-render SCENE -o OUT -q ARGS (under $run_limited);
# returns 0 if it wrote a non-empty OUT, else counts one failure that shows its stderr.
render_ok() {
    local name=$1 scene=$2 out=$3
    shift 3
    local log="$TMP/$name.stderr"
    if "${run_limited[@]}" "$BUILD/torusrt-render" "$scene" -o "$out" -q "$@" >/dev/null 2>"$log" </dev/null &&
        [ -s "$out" ]; then
        return 0
    fi
    fail "$name: torusrt-render $* did not produce $out: $(head -c 300 "$log")"
    return 1
}
# nowall CSV [SEPARATOR]: the CSV (default separator ',') without its wall-clock columns (those
# whose header names wall), for comparing two runs of the same points.
nowall() {
    awk -F"${2:-,}" 'NR == 1 { for (i = 1; i <= NF; i++) keep[i] = $i !~ /wall/ }
        { s = ""; for (i = 1; i <= NF; i++) if (keep[i]) s = s (s == "" ? "" : FS) $i; print s }' "$1"
}
