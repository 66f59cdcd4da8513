#!/usr/bin/env bash
# sim_remap_window.sh - adaptive's judgement of its guesses over past frames (--remap-window,
# --remap-margin): the window and margin are reported, the back-test covers min(window, frames
# scored) frames, the guess taken is the one its reason shows with the least mean ratio (the first
# on a tie) unless `frame`'s is within the margin of it, the frames stay the renderer's, and bad
# values exit 2 naming the option with no output.
#
# Usage (CTest runs it so): bash tests/cli/sim_remap_window.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
sim="$BUILD/torusrt-sim"
time_limit 300
scene=$(source_scene paper-image1) || exit 1
size=(--size 16x16)
anim=(--ips 2x2x2 --map cost --orbit 360 --frames 7 --remap adaptive)


"$BUILD/torusrt-render" "$scene" "${size[@]}" --orbit 360 --frames 7 -o "$TMP/ref_%d.png" -q || fail "renderer frames"
sim_ok default "$scene" "${size[@]}" "${anim[@]}" -o "$TMP/d_%d.png" --stats "$TMP/d.json"
sim_ok one "$scene" "${size[@]}" "${anim[@]}" --remap-window 1 -o "$TMP/w1_%d.png" --stats "$TMP/w1.json"
sim_ok three "$scene" "${size[@]}" "${anim[@]}" --remap-window 3 -o "$TMP/w3_%d.png" --stats "$TMP/w3.json"
sim_ok four "$scene" "${size[@]}" "${anim[@]}" --remap-window 4 -o "$TMP/w4_%d.png" --stats "$TMP/w4.json"
sim_ok margin0 "$scene" "${size[@]}" "${anim[@]}" --remap-margin 0 -o "$TMP/m0_%d.png" --stats "$TMP/m0.json"
sim_ok margin1 "$scene" "${size[@]}" "${anim[@]}" --remap-margin 1 -o "$TMP/m1_%d.png" --stats "$TMP/m1.json"

check "default window reported" [ "$(jq .animation.window "$TMP/d.json")" = 1 ]
check "the default is --remap-window 1" [ "$(jq -c '[.frames[].remap.reason]' "$TMP/d.json")" = \
    "$(jq -c '[.frames[].remap.reason]' "$TMP/w1.json")" ]
check "--remap-window 3 reported" [ "$(jq .animation.window "$TMP/w3.json")" = 3 ]
check "default margin reported" [ "$(jq .animation.margin "$TMP/d.json")" = 0 ]
"$sim" "$scene" "${size[@]}" "${anim[@]}" --remap-window 3 --remap-margin 0.25 -o "$TMP/sum_%d.png" \
    > "$TMP/sum.txt" 2>/dev/null </dev/null || fail "a run with its summary"
check "the summary names the window and margin ($(grep -m1 animation "$TMP/sum.txt"))" \
    grep -q "remap adaptive (guesses judged over 3 frames, margin 0.25)" "$TMP/sum.txt"
"$sim" "$scene" "${size[@]}" "${anim[@]}" -o "$TMP/sum1_%d.png" > "$TMP/sum1.txt" 2>/dev/null </dev/null ||
    fail "a default run with its summary"
check "the summary of the default: one frame ($(grep -m1 animation "$TMP/sum1.txt"))" \
    grep -q "remap adaptive (guesses judged over 1 frame, margin 0)" "$TMP/sum1.txt"
check "--remap-margin 1 reported" [ "$(jq .animation.margin "$TMP/m1.json")" = 1 ]
check "the default is --remap-margin 0" [ "$(jq -c '[.frames[].remap.reason]' "$TMP/d.json")" = \
    "$(jq -c '[.frames[].remap.reason]' "$TMP/m0.json")" ]
sim_ok static "$scene" "${size[@]}" --ips 2x2x2 --orbit 360 --frames 2 --remap static -o "$TMP/s_%d.png" \
    --stats "$TMP/s.json"
check "a policy other than adaptive reports no window" [ "$(jq '.animation | has("window")' "$TMP/s.json")" = false ]
check "a policy other than adaptive reports no margin" [ "$(jq '.animation | has("margin")' "$TMP/s.json")" = false ]

# Frames scored before frame k: k - 1 (frame 1's tables are the first scored, at frame 2), at most the window.
counts() { jq -c '[.frames[2:][].remap.reason | capture("back-tested on (?<n>[0-9]+) frame").n | tonumber]' "$1"; }
check "window 1: one frame each time ($(counts "$TMP/w1.json"))" [ "$(counts "$TMP/w1.json")" = "[1,1,1,1,1]" ]
check "window 3: 1, 2, then 3 frames ($(counts "$TMP/w3.json"))" [ "$(counts "$TMP/w3.json")" = "[1,2,3,3,3]" ]
check "window 4: 1, 2, 3, then 4 frames ($(counts "$TMP/w4.json"))" [ "$(counts "$TMP/w4.json")" = "[1,2,3,4,4]" ]

# The guess taken is `frame` if its mean ratio is within the run's margin of the least among those
# the reason lists, else the first with the least (the reason prints ratios to six decimals).
taken_is_least() {
    jq -e '.animation.margin as $margin | [.frames[2:][].remap.reason
            | (capture("guess (?<g>[a-z-]+)").g) as $g
            | [capture("best table: (?<l>[^)]*)\\)").l | split(", ")[] | split(" ") | {n: .[0], r: (.[1] | tonumber)}]
            | (map(.r) | min) as $m | (map(select(.n == "frame")) | .[0].r) as $f
            | (if $f <= $m * (1 + $margin) then "frame" else (map(select(.r == $m)) | .[0].n) end) == $g] | all' \
        "$1" >/dev/null
}
for w in d w1 w3 w4 m0 m1; do check "$w: the guess taken is the one the rule names" taken_is_least "$TMP/$w.json"; done
guesses() { jq -c '[.frames[2:][].remap.reason | capture("guess (?<g>[a-z-]+)").g]' "$1"; }
check "margin 1: frame is always taken ($(guesses "$TMP/m1.json"))" \
    [ "$(guesses "$TMP/m1.json")" = '["frame","frame","frame","frame","frame"]' ]
check "margin 0 takes another guess at least once ($(guesses "$TMP/m0.json"))" \
    [ "$(guesses "$TMP/m0.json")" != '["frame","frame","frame","frame","frame"]' ]
for w in d w1 w3 w4 m0 m1; do for k in 0 1 2 3 4 5 6; do
    check "$w: frame $k equals the renderer's" cmp -s "$TMP/ref_$k.png" "$TMP/${w}_$k.png"
done; done

# Bad values: exit 2, the option named, no output.
bad() { bad_option --remap-window "$@"; }
bad zero --orbit 90 --frames 2 --remap adaptive --remap-window 0
bad negative --orbit 90 --frames 2 --remap adaptive --remap-window -3
bad fraction --orbit 90 --frames 2 --remap adaptive --remap-window 2.5
bad word --orbit 90 --frames 2 --remap adaptive --remap-window four
bad spaced --orbit 90 --frames 2 --remap adaptive --remap-window " 4"
bad huge --orbit 90 --frames 2 --remap adaptive --remap-window 99999999999999999999
bad not-adaptive --orbit 90 --frames 2 --remap every-frame --remap-window 2
bad with-preview --orbit 90 --frames 2 --remap adaptive --remap-pilot 0.25 --remap-window 2
bad single-image --remap-window 2
badm() { bad_option --remap-margin "$@"; }
badm negative --orbit 90 --frames 2 --remap adaptive --remap-margin -0.1
badm above-one --orbit 90 --frames 2 --remap adaptive --remap-margin 1.5
badm word --orbit 90 --frames 2 --remap adaptive --remap-margin some
badm nan --orbit 90 --frames 2 --remap adaptive --remap-margin nan
badm empty --orbit 90 --frames 2 --remap adaptive --remap-margin ""
badm not-adaptive --orbit 90 --frames 2 --remap oracle --remap-margin 0.1
badm with-preview --orbit 90 --frames 2 --remap adaptive --remap-pilot 0.25 --remap-margin 0.1
badm single-image --remap-margin 0.1
finish
