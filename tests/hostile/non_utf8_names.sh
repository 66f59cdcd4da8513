#!/usr/bin/env bash
# non_utf8_names.sh - a scene or timing file whose name is not UTF-8 ($'\xff.nff') does not fail
# a run with --stats at its end: torusrt-sim and torusrt-render write the image and a JSON report
# that is valid UTF-8 (the name's byte shown as U+FFFD), exit 0.
#
# Usage (CTest runs it so): bash tests/hostile/non_utf8_names.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim torusrt-render
command -v jq >/dev/null || { echo "$TEST_NAME: jq is not installed; skipped"; exit 77; }
time_limit 60
f=$(source_scene paper-image1) || exit 1
cd "$TMP" || exit 1
scene=$'\xff.nff' timing=$'t\xfe.timing'
cp "$f" "$scene"
printf 'handover_send 100\n' >"$timing"
for exe in torusrt-sim torusrt-render; do
    rm -f o.png r.json
    "${run_limited[@]}" "$BUILD/$exe" "$scene" -q -o o.png --size 8x8 --timing "$timing" --stats r.json \
        >/dev/null 2>err.txt </dev/null
    rc=$?
    check "$exe, names not UTF-8, --stats: exit $rc, expected 0: $(head -c 300 err.txt)" [ "$rc" -eq 0 ]
    check "$exe, names not UTF-8: the image" [ -s o.png ]
    check "$exe, names not UTF-8: the report is JSON" jq -e . r.json >/dev/null
    check "$exe, names not UTF-8: the scene's name in it, its byte replaced" \
        test "$(jq -r .scene r.json 2>/dev/null)" = $'\xef\xbf\xbd.nff'
done
finish
