#!/usr/bin/env bash
# spd_style.sh - the SPD-style files in tests/spd_style load, render something, and
# torusrt-sim on a 2x2x2 torus reproduces torusrt-render's PNG byte for byte (cmp).
#
# Usage (CTest runs it so): bash tests/cli/spd_style.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-render torusrt-sim
time_limit 300
shopt -s nullglob
files=("$SRC"/tests/spd_style/*.nff)
check "no files in tests/spd_style" [ ${#files[@]} -ge 3 ]
for f in "${files[@]}"; do
    name=$(basename "$f" .nff)
    render_ok "$name" "$f" "$TMP/$name-render.png" --stats "$TMP/$name.json" || continue
    shaded=$(json "$TMP/$name.json" .ops.shadings)
    check "$name: no object was shaded" [ "$shaded" -gt 0 ]
    if "${run_limited[@]}" "$BUILD/torusrt-sim" "$f" -o "$TMP/$name-sim.png" -q --ips 2x2x2 \
        >/dev/null 2>"$TMP/$name-sim.stderr" </dev/null; then
        check "$name: torusrt-sim's PNG differs from torusrt-render's" \
            cmp -s "$TMP/$name-render.png" "$TMP/$name-sim.png"
    else
        fail "$name: torusrt-sim failed: $(head -c 300 "$TMP/$name-sim.stderr")"
    fi
done
finish
