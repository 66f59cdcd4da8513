#!/usr/bin/env bash
# sim_frames.sh - animations in torusrt-sim: every frame's PNG equals the renderer's frame under
# every --remap policy, a frame's image time equals a single run with its camera and mapping,
# the frames[] / animation JSON and the CSV add up (a frame's packets, its primaries included, are
# a single run's), migration is zero when the mapping stays,
# and bad input (--frames 0, a bad camera path, bad --remap) is exit 2 with no output.
#
# Usage (CTest runs it so): bash tests/cli/sim_frames.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
sim="$BUILD/torusrt-sim"
render="$BUILD/torusrt-render"
time_limit 300
scene=$(source_scene paper-image2) || exit 1
scene1=$(source_scene paper-image1) || exit 1
size=(--size 32x32)

sum() { jq "[$2] | add" "$1"; }
close() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-7 * (a < 0 ? -a : a) + 1e-12) }'; }
differs() { ! cmp -s "$1" "$2"; }

# The renderer's frames, the golden images.
mkdir "$TMP/ref"
"$render" "$scene" "${size[@]}" --orbit 360 --frames 4 -o "$TMP/ref/f_%d.png" -q || fail "renderer frames"

# Every policy, flat torus and a cluster, gives the renderer's frames byte for byte.
for policy in static every-frame adaptive oracle; do
    for named in "cost:--ips 2x2x2 --map cost" "cluster:--ips 2x2 --cluster 2 --map cost" "cyclic:--ips 4x2x2"; do
        tag="$policy-${named%%:*}"
        shape=${named#*:}
        mkdir "$TMP/$tag"
        # shellcheck disable=SC2086 # the shape is a list of options
        sim_ok "$tag" "$scene" "${size[@]}" $shape --orbit 360 --frames 4 --remap "$policy" \
            -o "$TMP/$tag/f_%d.png" --stats "$TMP/$tag.json" --frames-csv "$TMP/$tag.csv" || continue
        for k in 0 1 2 3; do
            check "$tag: frame $k equals the renderer's" cmp -s "$TMP/ref/f_$k.png" "$TMP/$tag/f_$k.png"
        done
        j="$TMP/$tag.json"
        check "$tag: 4 frames in the JSON" [ "$(jq '.frames | length' "$j")" = 4 ]
        check "$tag: policy named" [ "$(jq -r .animation.policy "$j")" = "$policy" ]
        total=$(jq .animation.total_s "$j")
        parts=$(jq '[.frames[].image_time_s] + [.frames[].migration_time_s] | add' "$j")
        check "$tag: total = sum of frame times + migration ($total vs $parts)" close "$total" "$parts"
        check "$tag: conserved" [ "$(jq .packets.conserved "$j")" = true ]
        check "$tag: the frames' packets add up to the packets created ($(sum "$j" '.frames[].packets'))" \
            [ "$(sum "$j" '.frames[].packets')" = "$(jq .packets.created.total "$j")" ]
        check "$tag: CSV has a header and 4 rows" [ "$(wc -l <"$TMP/$tag.csv")" = 5 ]
        csv_sum=$(awk -F, 'NR > 1 { s += $4 } END { printf "%.9g", s }' "$TMP/$tag.csv")
        check "$tag: CSV image times add up to the JSON's" close "$(sum "$j" '.frames[].image_time_s')" "$csv_sum"
    done
done

# static keeps the mapping: no migration at all. oracle's migration is not charged.
j="$TMP/static-cost.json"
check "static: zero migration bytes" [ "$(sum "$j" '.frames[].migration_bytes')" = 0 ]
check "static: every later frame keeps" [ "$(jq -r '[.frames[1:][].remap.decision] | unique | join(",")' "$j")" = keep ]
j="$TMP/every-frame-cost.json"
check "every-frame: the mapping changes, bytes move" [ "$(sum "$j" '.frames[].migration_bytes')" -gt 0 ]
check "every-frame: a frame with no change has no bytes" \
    [ "$(jq '[.frames[] | select(.migration.cells == 0 and .migration_bytes != 0)] | length' "$j")" = 0 ]
j="$TMP/oracle-cost.json"
check "oracle: migration is free" [ "$(sum "$j" '.frames[].migration_time_s')" = 0 ]

# A frame's image time equals a single run with that frame's camera (the half turn of
# paper-image1's view: from 4 5 30 -> -4 5 -30) under the same mapping.
angle1=$(awk '$1 == "angle" { print $2 }' "$scene1")  # the scene's own view angle
printf '4 5 30 0 0 0 0 1 0 %s\n-4 5 -30 0 0 0 0 1 0 %s\n' "$angle1" "$angle1" >"$TMP/two.txt"
sed 's/^from 4 5 30/from -4 5 -30/' "$scene1" >"$TMP/half.nff"
check "premise: the half-turn scene differs in its view" differs "$scene1" "$TMP/half.nff"
sim_ok two "$scene1" "${size[@]}" --ips 4x2x2 --camera-path "$TMP/two.txt" -o "$TMP/two_%d.png" \
    --stats "$TMP/two.json"
sim_ok half "$TMP/half.nff" "${size[@]}" --ips 4x2x2 -o "$TMP/half.png" --stats "$TMP/half.json"
sim_ok plain "$scene1" "${size[@]}" --ips 4x2x2 -o "$TMP/plain.png" --stats "$TMP/plain.json"
check "frame 1 equals the single run's image" cmp -s "$TMP/two_1.png" "$TMP/half.png"
check "frame 1's time equals the single run's" \
    [ "$(jq .frames[1].image_time_s "$TMP/two.json")" = "$(jq .sim_time_s "$TMP/half.json")" ]
check "frame 0's time equals the plain run's" \
    [ "$(jq .frames[0].image_time_s "$TMP/two.json")" = "$(jq .sim_time_s "$TMP/plain.json")" ]
check "frame 1's packets, primaries included, equal the single run's" \
    [ "$(jq .frames[1].packets "$TMP/two.json")" = "$(jq .packets.created.total "$TMP/half.json")" ]
check "frame 0's packets equal the plain run's" \
    [ "$(jq .frames[0].packets "$TMP/two.json")" = "$(jq .packets.created.total "$TMP/plain.json")" ]
check "frame 1 starts when frame 0 ends" \
    [ "$(jq .frames[1].start_s "$TMP/two.json")" = "$(jq .frames[0].image_time_s "$TMP/two.json")" ]
check "a plain run has no frames" [ "$(jq 'has("frames")' "$TMP/plain.json")" = false ]

# Deterministic: the same animation twice gives the same figures.
sim_ok again "$scene" "${size[@]}" --ips 2x2x2 --map cost --orbit 360 --frames 4 --remap adaptive \
    -o "$TMP/again_%d.png" --stats "$TMP/again.json"
check "adaptive twice: same frame times and decisions" [ "$(jq -c '[.frames[] | [.image_time_s, .remap.decision, .migration_bytes]]' \
    "$TMP/again.json")" = "$(jq -c '[.frames[] | [.image_time_s, .remap.decision, .migration_bytes]]' \
    "$TMP/adaptive-cost.json")" ]
# Adaptive names its guess: frame 0's load for frame 1, a back-tested guess from frame 2 on, the
# trend among them from frame 3 on (4 frames: frames 1..3 decided).
check "adaptive: frame 1 guesses frame 0's load" \
    [ "$(jq -r '.frames[1].remap.reason | test("guess frame,")' "$TMP/again.json")" = true ]
check "adaptive: frames 2 and 3 back-test their guess, the trend from frame 3" \
    [ "$(jq -c '[.frames[2:][].remap.reason | [test("back-tested on [0-9]+ frames?, mean ratio to the best table: frame "), test("trend-blurred ")]]' \
        "$TMP/again.json")" = '[[true,false],[true,true]]' ]

# Bad input: exit 2, a message naming the option or FILE:LINE, no output at all.
bad() { # bad NAME PATTERN ARGS...: exit 2, stderr matches PATTERN, $TMP/bad empty
    local name=$1 pattern=$2
    shift 2
    rm -rf "$TMP/bad" && mkdir "$TMP/bad"
    "${run_limited[@]}" "$sim" "$scene" "${size[@]}" -q "$@" >/dev/null 2>"$TMP/bad.stderr" </dev/null
    local rc=$?
    check "$name: exit 2 (got $rc)" [ "$rc" = 2 ]
    check "$name: message '$pattern' ($(head -c 200 "$TMP/bad.stderr"))" grep -q -- "$pattern" "$TMP/bad.stderr"
    check "$name: no output" [ -z "$(ls "$TMP/bad")" ]
}
printf '0 15 10 0 0.5 -6 0 1 0 50.5\n1 2 3\n' >"$TMP/short.txt"
printf '0 15 10 0 0.5 -6 0 1 0 50.5\n0 15 10 0 15 10 0 1 0 50\n' >"$TMP/same.txt"
out=(-o "$TMP/bad/f_%d.png" --stats "$TMP/bad/s.json" --frames-csv "$TMP/bad/f.csv")
bad frames0 "--frames 0" --frames 0 --orbit 90 "${out[@]}"
bad short-line "short.txt:2" --camera-path "$TMP/short.txt" "${out[@]}"
bad from-is-at "same.txt:2" --camera-path "$TMP/same.txt" "${out[@]}"
bad missing-path "nothing.txt" --camera-path "$TMP/nothing.txt" "${out[@]}"
bad remap-word "--remap" --orbit 90 --frames 2 --remap sometimes "${out[@]}"
bad remap-alone "--remap" --remap every-frame -o "$TMP/bad/x.png"
bad csv-alone "--frames-csv" --frames-csv "$TMP/bad/f.csv" -o "$TMP/bad/x.png"
bad no-pattern "-o" --orbit 90 --frames 2 -o "$TMP/bad/x.png"
bad frames-no-camera "--frames" --frames 3 "${out[@]}"
bad frames-disagree "--frames 5" --frames 5 --camera-path "$TMP/two.txt" "${out[@]}"
finish
