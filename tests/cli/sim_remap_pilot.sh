#!/usr/bin/env bash
# sim_remap_pilot.sh - adaptive's host preview (--remap-pilot): the preview's pixel count, its
# host time charged only past the previous frame's image time (zero when it fits, the excess
# when it does not), the frames still the renderer's, and bad values exit 2 naming the option.
#
# Usage (CTest runs it so): bash tests/cli/sim_remap_pilot.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
sim="$BUILD/torusrt-sim"
time_limit 300
scene=$(source_scene paper-image2) || exit 1
size=(--size 16x16)

close() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-7 * (a < 0 ? -a : a) + 1e-12) }'; }

# Two frames of the same view: frame 1's full-resolution preview (--remap-pilot 1) costs the host
# frame 1's T(1), which is frame 0's T(1) as well.
printf '0 15 10 0 0.5 -6 0 1 0 50.5\n0 15 10 0 0.5 -6 0 1 0 50.5\n' >"$TMP/still.txt"

# One processor: frame 0 takes at least its T(1), so the host's pilot fits inside it: charge 0.
sim_ok one "$scene" "${size[@]}" --ips 1x1x1 --camera-path "$TMP/still.txt" --remap adaptive --remap-pilot 1 \
    -o "$TMP/one_%d.png" --stats "$TMP/one.json"
j="$TMP/one.json"
check "one: the preview has all 256 pixels" [ "$(jq .frames[1].host_pilot.pixels "$j")" = 256 ]
check "one: host time is frame 1's T(1)" close "$(jq .frames[1].host_pilot.time_s "$j")" "$(jq .frames[1].t1_s "$j")"
check "one: premise, the pilot fits in frame 0 ($(jq .frames[1].host_pilot.time_s "$j") <= $(jq .frames[0].image_time_s "$j"))" \
    awk -v h="$(jq .frames[1].host_pilot.time_s "$j")" -v t="$(jq .frames[0].image_time_s "$j")" 'BEGIN { exit !(h <= t) }'
check "one: nothing charged" [ "$(jq .frames[1].host_pilot.charged_s "$j")" = 0 ]
check "one: total charges nothing" [ "$(jq .animation.host_pilot_charged_s "$j")" = 0 ]

# Eight processors: frame 0 takes less than T(1), so the excess delays frame 1.
sim_ok eight "$scene" "${size[@]}" --ips 2x2x2 --map cost --camera-path "$TMP/still.txt" --remap adaptive \
    --remap-pilot 1 -o "$TMP/eight_%d.png" --stats "$TMP/eight.json" --frames-csv "$TMP/eight.csv"
j="$TMP/eight.json"
host=$(jq .frames[1].host_pilot.time_s "$j")
prev=$(jq .frames[0].image_time_s "$j")
charged=$(jq .frames[1].host_pilot.charged_s "$j")
check "eight: premise, the pilot exceeds frame 0 ($host > $prev)" awk -v h="$host" -v t="$prev" 'BEGIN { exit !(h > t) }'
check "eight: charged = host time - frame 0's time" close "$charged" "$(awk -v h="$host" -v t="$prev" 'BEGIN { printf "%.12g", h - t }')"
check "eight: frame 1 starts after frame 0, its migration and the charge" close "$(jq .frames[1].start_s "$j")" \
    "$(jq '.frames[0].image_time_s + .frames[1].migration_time_s + .frames[1].host_pilot.charged_s' "$j")"
check "eight: total = images + migration + charge" close "$(jq .animation.total_s "$j")" \
    "$(jq '[.frames[] | .image_time_s + .migration_time_s + .host_pilot.charged_s] | add' "$j")"
check "eight: frame 0 has no preview" [ "$(jq '.frames[0].host_pilot | [.pixels, .charged_s] | add' "$j")" = 0 ]
check "eight: the CSV's charge column" [ "$(awk -F, 'NR == 3 { print $NF }' "$TMP/eight.csv")" != 0 ]

# A quarter of the pixels: 8x8 of 16x16; the frames stay the renderer's.
"$BUILD/torusrt-render" "$scene" "${size[@]}" --orbit 90 --frames 3 -o "$TMP/ref_%d.png" -q || fail "renderer frames"
sim_ok quarter "$scene" "${size[@]}" --ips 2x2x2 --map cost --orbit 90 --frames 3 --remap adaptive \
    --remap-pilot 0.25 -o "$TMP/q_%d.png" --stats "$TMP/q.json"
check "quarter: 64-pixel previews" [ "$(jq -c '[.frames[1:][].host_pilot.pixels] | unique' "$TMP/q.json")" = "[64]" ]
for k in 0 1 2; do check "quarter: frame $k equals the renderer's" cmp -s "$TMP/ref_$k.png" "$TMP/q_$k.png"; done
# The default: no preview, nothing charged.
sim_ok default "$scene" "${size[@]}" --ips 2x2x2 --map cost --orbit 90 --frames 3 --remap adaptive \
    -o "$TMP/d_%d.png" --stats "$TMP/d.json"
check "default: no preview" [ "$(jq '[.frames[].host_pilot.pixels] | add' "$TMP/d.json")" = 0 ]

# Bad values: exit 2, the option named, no output.
bad() { bad_option --remap-pilot "$@"; }
bad word --orbit 90 --frames 2 --remap adaptive --remap-pilot half
bad negative --orbit 90 --frames 2 --remap adaptive --remap-pilot -0.5
bad above-one --orbit 90 --frames 2 --remap adaptive --remap-pilot 1.5
bad nan --orbit 90 --frames 2 --remap adaptive --remap-pilot nan
bad not-adaptive --orbit 90 --frames 2 --remap every-frame --remap-pilot 0.25
bad no-remap --orbit 90 --frames 2 --remap-pilot 0.25
bad single-image --remap-pilot 0.25
finish
