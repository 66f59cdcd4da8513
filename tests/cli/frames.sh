#!/usr/bin/env bash
# frames.sh - animations in torusrt-render: orbit and camera-path frames against plain renders
# byte for byte, the frame pattern, the frames array of the JSON, and every rejected input
# (message, exit status, no output file).
#
# Usage (CTest runs it so): bash tests/cli/frames.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-render
render="$BUILD/torusrt-render"
time_limit 120
scene=$(source_scene paper-image1-planar-z) || exit 1
size=(--size 40x40)

# The scene's own camera (paper-image1-planar-z: from 4 5 30, at 0 0 0, up 0 1 0, angle 36.5).
view=$(awk '$1 == "from" || $1 == "at" || $1 == "up" || $1 == "angle" { $1 = ""; printf "%s", $0 }' "$scene")
check "the scene's view is the one this test computes by hand" \
    [ "$(echo $view)" = "4 5 30 0 0 0 0 1 0 36.5" ]

render_ok plain "$scene" "$TMP/plain.png" "${size[@]}" || exit 1

# anim_ok NAME SCENE PATTERN FIRST ARGS...: an animation run that must succeed and write FIRST.
anim_ok() {
    local name=$1 scene=$2 pattern=$3 first=$4
    shift 4
    if "${run_limited[@]}" "$render" "$scene" -o "$pattern" -q "$@" >/dev/null 2>"$TMP/$name.stderr" \
        </dev/null && [ -s "$first" ]; then
        pass
    else
        fail "$name: torusrt-render -o $pattern $* did not write $first: $(head -c 300 "$TMP/$name.stderr")"
    fi
}
differs() { ! cmp -s "$1" "$2"; }

# An orbit of 0 degrees: every frame is the plain image.
mkdir "$TMP/o0"
anim_ok orbit0 "$scene" "$TMP/o0/f_%03d.png" "$TMP/o0/f_000.png" "${size[@]}" --orbit 0 --frames 3 \
    --stats "$TMP/o0.json"
for k in 000 001 002; do
    check "orbit 0: frame $k equals the plain render" cmp -s "$TMP/plain.png" "$TMP/o0/f_$k.png"
done
check "orbit 0: exactly three files" [ "$(ls "$TMP/o0" | wc -l)" -eq 3 ]

# Frame 0 of any orbit is the scene's own view; the others differ from it.
mkdir "$TMP/o37"
anim_ok orbit37 "$scene" "$TMP/o37/f_%d.png" "$TMP/o37/f_0.png" "${size[@]}" --orbit 37.5 --frames 2
check "orbit 37.5: frame 0 equals the plain render" cmp -s "$TMP/plain.png" "$TMP/o37/f_0.png"
check "orbit 37.5: frame 1 differs" differs "$TMP/plain.png" "$TMP/o37/f_1.png"

# A full orbit over 4 frames: frame 2 is the half turn about the y axis through 'at' = 0.
# By hand: the eye's part along up (y = 5) stays, the rest is negated: from -4 5 -30.
mkdir "$TMP/o360" "$TMP/path"
anim_ok orbit360 "$scene" "$TMP/o360/f_%d.png" "$TMP/o360/f_0.png" "${size[@]}" --orbit 360 --frames 4 \
    --stats "$TMP/o360.json"
printf '# the half turn, by hand\n\n-4 5 -30   0 0 0   0 1 0   36.5  # eye mirrored\n' >"$TMP/half.txt"
anim_ok path "$scene" "$TMP/path/p_%d.png" "$TMP/path/p_0.png" "${size[@]}" --camera-path "$TMP/half.txt"
check "orbit 360/4 frame 2 equals the camera-path half turn" cmp -s "$TMP/o360/f_2.png" "$TMP/path/p_0.png"
check "a full orbit ends one step before the start (4 files, no frame 4)" \
    [ "$(ls "$TMP/o360" | wc -l)" -eq 4 ]
check "orbit 360/4 frame 1 differs from frame 3" differs "$TMP/o360/f_1.png" "$TMP/o360/f_3.png"

# The JSON frames array and its totals.
if [ -s "$TMP/o360.json" ]; then
    check "frames array has 4 entries" [ "$(json "$TMP/o360.json" '.frames | length')" = 4 ]
    check "frame_count 4" [ "$(json "$TMP/o360.json" '.frame_count')" = 4 ]
    check "frame 2's camera is the half turn" \
        [ "$(json "$TMP/o360.json" '.frames[2].camera.from | map(tostring) | join(" ")')" = "-4 5 -30" ]
    check "frame files in the JSON" [ "$(json "$TMP/o360.json" '.frames[3].file')" = "$TMP/o360/f_3.png" ]
    check "ops total is the sum of the frames'" [ "$(json "$TMP/o360.json" \
        '([.frames[].ops.tests_hit] | add) == .ops.tests_hit')" = true ]
    check "t1_s total is the sum of the frames'" [ "$(json "$TMP/o360.json" \
        '((([.frames[].t1_s] | add) - .t1_s) | fabs) < 1e-9 * .t1_s')" = true ]
    check "packets total is the sum of the frames'" [ "$(json "$TMP/o360.json" \
        '([.frames[].packets.created.total] | add) == .packets.created.total')" = true ]
    check "frame 0 counts equal the single frame of the orbit of 0" [ "$(jq -s \
        '.[0].frames[0].ops == .[1].frames[0].ops' "$TMP/o360.json" "$TMP/o0.json")" = true ]
else
    fail "no JSON from the 360 orbit"
fi

# Determinism: the same animation twice gives the same bytes.
mkdir "$TMP/again"
anim_ok again "$scene" "$TMP/again/f_%d.png" "$TMP/again/f_0.png" "${size[@]}" --orbit 360 --frames 4
for k in 0 1 2 3; do
    check "determinism: frame $k" cmp -s "$TMP/o360/f_$k.png" "$TMP/again/f_$k.png"
done

# A single-frame run is unchanged: no pattern expansion, the same file name.
render_ok literal "$scene" "$TMP/lit_%d.png" "${size[@]}"
check "without animation options -o is a plain name" cmp -s "$TMP/plain.png" "$TMP/lit_%d.png"

# rejected STATUS WHAT ARGS...: torusrt-render exits STATUS, prints WHAT, leaves no file in out/.
rejected() {
    local status=$1 what=$2 rc
    shift 2
    rm -rf "$TMP/out" && mkdir "$TMP/out"
    "${run_limited[@]}" "$render" "$scene" -q "${size[@]}" "$@" >/dev/null 2>"$TMP/err" </dev/null
    rc=$?
    check "$* exits $rc, expected $status ($(head -c 200 "$TMP/err"))" [ "$rc" -eq "$status" ]
    check "$*: message has '$what'" grep -qF -- "$what" "$TMP/err"
    check "$*: no output" [ -z "$(ls -A "$TMP/out")" ]
}
out="$TMP/out/f_%d.png"
rejected 2 "--frames 0" -o "$out" --frames 0 --orbit 90
rejected 2 "--frames -3" -o "$out" --frames -3 --orbit 90
rejected 2 "needs --orbit" -o "$out" --frames 3
rejected 2 "needs --frames" -o "$out" --orbit 90
rejected 2 "not both" -o "$out" --frames 2 --orbit 90 --camera-path "$TMP/half.txt"
rejected 2 "holds 1 camera lines" -o "$out" --frames 2 --camera-path "$TMP/half.txt"
rejected 2 "--orbit 'nan'" -o "$out" --frames 2 --orbit nan
rejected 2 "folder" -o "$TMP/out/none/f_%d.png" --frames 2 --orbit 90
rejected 2 "--stats" -o "$out" --frames 2 --orbit 90 --stats "$TMP/out/none/s.json"
for pattern in f.png f_%d_%d.png f_%s.png f_%5d.png f_%i.png f_%-3d.png f_%00d.png f_%100d.png f_%d%; do
    rejected 2 "-o '$TMP/out/$pattern'" -o "$TMP/out/$pattern" --frames 2 --orbit 90
done

# An output named like an existing folder is refused before any frame is rendered: no frame is left.
rm -rf "$TMP/out" && mkdir -p "$TMP/out/stats.json"
"${run_limited[@]}" "$render" "$scene" -q "${size[@]}" -o "$out" --orbit 90 --frames 3 \
    --stats "$TMP/out/stats.json" >/dev/null 2>"$TMP/err" </dev/null
rc=$?
check "a folder as --stats exits 2 (got $rc)" [ "$rc" -eq 2 ]
check "a folder as --stats is named" grep -qF "$TMP/out/stats.json" "$TMP/err"
check "a folder as --stats leaves no frame: $(ls "$TMP/out" | tr '\n' ' ')" [ "$(ls -A "$TMP/out")" = stats.json ]

# Camera path file errors: FILE:LINE: and exit 2, no output.
bad() {
    local name=$1 line=$2
    printf "$3" >"$TMP/$name.txt"
    rejected 2 "$TMP/$name.txt:$line: " -o "$out" --camera-path "$TMP/$name.txt" --stats "$TMP/out/s.json"
}
good='0 0 30 0 0 0 0 1 0 28.5\n'
bad fields 2 "$good""0 0 30 0 0 0 0 1 28.5\n"
bad extra 1 "0 0 30 0 0 0 0 1 0 28.5 7\n"
bad nonfinite 3 "$good$good""0 0 nan 0 0 0 0 1 0 28.5\n"
bad infinite 1 "0 0 30 0 0 0 0 1 0 inf\n"
bad word 1 "0 0 30 0 0 0 0 1 0 wide\n"
bad huge 1 "0 0 1e31 0 0 0 0 1 0 28.5\n"
bad same 2 "# c\n1 2 3 1 2 3 0 1 0 28.5\n"
bad parallel 1 "0 0 30 0 0 0 0 0 1 28.5\n"
bad angle 1 "0 0 30 0 0 0 0 1 0 180\n"
bad angle0 2 "$good""0 0 30 0 0 0 0 1 0 -5\n"
bad empty 2 "# nothing\n\n"
bad long 2 "$good$(printf '%5000s' '')\n"
# Not a regular file, and a missing file: named, exit 2, no output.
rejected 2 "--camera-path: $TMP: is a folder, not a regular file" -o "$out" --camera-path "$TMP"
rejected 2 "$TMP/missing.txt: cannot open" -o "$out" --camera-path "$TMP/missing.txt"
if command -v mkfifo >/dev/null; then
    mkfifo "$TMP/fifo"
    rejected 2 "$TMP/fifo: is a FIFO, not a regular file" -o "$out" --camera-path "$TMP/fifo"
fi

finish
