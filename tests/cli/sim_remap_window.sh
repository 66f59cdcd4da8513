#!/usr/bin/env bash
# sim_remap_window.sh - adaptive's judgement of its guesses over past frames (--remap-window):
# the window is reported, the back-test covers min(window, frames scored) frames, the guess taken
# is the one its reason shows with the least mean ratio (the first on a tie), the frames stay the
# renderer's, and bad values exit 2 naming the option with no output.
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

check "default window reported" [ "$(jq .animation.window "$TMP/d.json")" = 1 ]
check "the default is --remap-window 1" [ "$(jq -c '[.frames[].remap.reason]' "$TMP/d.json")" = \
    "$(jq -c '[.frames[].remap.reason]' "$TMP/w1.json")" ]
check "--remap-window 3 reported" [ "$(jq .animation.window "$TMP/w3.json")" = 3 ]
sim_ok static "$scene" "${size[@]}" --ips 2x2x2 --orbit 360 --frames 2 --remap static -o "$TMP/s_%d.png" \
    --stats "$TMP/s.json"
check "a policy other than adaptive reports no window" [ "$(jq '.animation | has("window")' "$TMP/s.json")" = false ]

# Frames scored before frame k: k - 1 (frame 1's tables are the first scored, at frame 2), at most the window.
counts() { jq -c '[.frames[2:][].remap.reason | capture("back-tested on (?<n>[0-9]+) frame").n | tonumber]' "$1"; }
check "window 1: one frame each time ($(counts "$TMP/w1.json"))" [ "$(counts "$TMP/w1.json")" = "[1,1,1,1,1]" ]
check "window 3: 1, 2, then 3 frames ($(counts "$TMP/w3.json"))" [ "$(counts "$TMP/w3.json")" = "[1,2,3,3,3]" ]
check "window 4: 1, 2, 3, then 4 frames ($(counts "$TMP/w4.json"))" [ "$(counts "$TMP/w4.json")" = "[1,2,3,4,4]" ]

# The guess taken is the first with the least mean ratio among those the reason lists.
taken_is_least() {
    jq -e '[.frames[2:][].remap.reason
            | (capture("guess (?<g>[a-z-]+)").g) as $g
            | [capture("best table: (?<l>[^)]*)\\)").l | split(", ")[] | split(" ") | {n: .[0], r: (.[1] | tonumber)}]
            | (map(.r) | min) as $m | (map(select(.r == $m)) | .[0].n) == $g] | all' "$1" >/dev/null
}
for w in d w1 w3 w4; do check "$w: the guess taken has the least mean ratio" taken_is_least "$TMP/$w.json"; done
for w in d w1 w3 w4; do for k in 0 1 2 3 4 5 6; do
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
finish
