#!/usr/bin/env bash
# hostile_files.sh - scene and timing paths that are not regular files: /dev/zero as the timing
# file (an unbounded read before), a FIFO with no writer as the scene or timing file (a blocking
# open hung before), a directory. Both executables must exit 1 at once with a message naming the
# path, and leave no output file. A scene whose bad keyword holds non-ASCII bytes is quoted with
# them escaped, and so is a control byte in its name.
#
# Usage (CTest runs it so): bash tests/cli/hostile_files.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-render torusrt-sim
time_limit 30
scene=$(source_scene one-pixel) || exit 1
mkfifo "$TMP/fifo"
esc=$'\033'
printf 'v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 4 4\n\xc2\x9b2J 1 2 3\n' >"$TMP/e${esc}c.nff"

# expect_refused NAME EXE PATTERN ARGS...
expect_refused() {
    local name=$1 exe=$2 pattern=$3
    shift 3
    local out="$TMP/out_$name"
    mkdir -p "$out"
    "${run_limited[@]}" "$BUILD/$exe" "$@" -o "$out/img.png" -q >/dev/null 2>"$TMP/$name.stderr" </dev/null
    local rc=$?
    check "$name: exit status $rc, expected 1 (124 = hung): $(head -c 300 "$TMP/$name.stderr")" [ "$rc" -eq 1 ]
    check "$name: stderr lacks '$pattern': $(head -c 300 "$TMP/$name.stderr")" grep -qF -- "$pattern" "$TMP/$name.stderr"
    check "$name: left files behind" [ -z "$(ls -A "$out")" ]
}

for exe in torusrt-render torusrt-sim; do
    expect_refused "$exe-timing-dev-zero" "$exe" "/dev/zero: is a character device, not a regular file" "$scene" --timing /dev/zero
    expect_refused "$exe-timing-fifo" "$exe" "$TMP/fifo: is a FIFO, not a regular file" "$scene" --timing "$TMP/fifo"
    expect_refused "$exe-scene-fifo" "$exe" "$TMP/fifo: is a FIFO, not a regular file" "$TMP/fifo"
    expect_refused "$exe-scene-dir" "$exe" "$TMP: is a folder, not a regular file" "$TMP"
    expect_refused "$exe-escaped" "$exe" "e\\x1bc.nff:2: unknown keyword '\\xc2\\x9b2J'" "$TMP/e${esc}c.nff"
    check "$exe: a raw ESC byte reached stderr" [ "$(tr -d -c '\033' <"$TMP/$exe-escaped.stderr" | wc -c)" -eq 0 ]
done
finish
