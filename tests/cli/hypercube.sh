#!/usr/bin/env bash
# --topology hypercube end to end (paper-image1 at 32x32):
# - the 4-cube (--ips 4x2x2): the image is torusrt-render's, packets are conserved, 16 x 4 links
#   named d0..d3, one channel per link; with finite buffers (--queue 1) under flow classes it
#   finishes (e-cube routes cannot deadlock) with the same image;
# - the 6-cube (--ips 4x4x4) is the 4x4x4 torus's graph and the Gray-code placement keeps the
#   cyclic mapping's hop distances: the same links (384) and the same packet hops as the torus;
# - --map cost and --map scatter on the 3-cube give the reference image, packets conserved;
# - the summary names the cube; --route-ties is idle on it;
# - --ips 6x4x4 is refused (exit 2) naming --ips, with no output.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
time_limit 300
sim="$BUILD/torusrt-sim"
scene="$SRC/scenes/paper-image1.nff"
size=(--size 32x32)
render_ok ref "$scene" "$TMP/ref.png" "${size[@]}" || { finish; exit 1; }
common=("$scene" "${size[@]}" --t1 1)

# Checks of a run whose stats are $TMP/NAME.json and image $TMP/NAME.png.
image_and_packets() {
    check "$1: reference image" cmp -s "$TMP/ref.png" "$TMP/$1.png"
    check "$1: packets conserved" test "$(json "$TMP/$1.json" .packets.conserved)" = true
}

if sim_ok cube4 "${common[@]}" --ips 4x2x2 --topology hypercube -o "$TMP/cube4.png" --stats "$TMP/cube4.json"; then
    image_and_packets cube4
    check "cube4: topology reported" test "$(json "$TMP/cube4.json" .config.topology)" = hypercube
    check "cube4: 64 links" test "$(json "$TMP/cube4.json" .links.count)" = 64
    check "cube4: links named d0..d3" test "$(jq -c '[.links.per_link[].dir] | unique' "$TMP/cube4.json")" = \
        '["d0","d1","d2","d3"]'
    check "cube4: every node has 4 links out" test "$(jq -c '[.links.per_link | group_by(.from)[] | length] | unique' \
        "$TMP/cube4.json")" = '[4]'
    check "cube4: one channel per link" test "$(json "$TMP/cube4.json" .flow.channels_per_link)" = 1
fi
if sim_ok cube4-q1 "${common[@]}" --ips 4x2x2 --topology hypercube --queue 1 -o "$TMP/cube4-q1.png" \
    --stats "$TMP/cube4-q1.json"; then
    image_and_packets cube4-q1
    check "cube4-q1: capacity kept" test "$(json "$TMP/cube4-q1.json" '.flow.high_water <= 1')" = true
fi

for t in hypercube torus; do
    sim_ok "six-$t" "${common[@]}" --ips 4x4x4 --topology "$t" -o "$TMP/six-$t.png" --stats "$TMP/six-$t.json" &&
        image_and_packets "six-$t"
done
if [ -f "$TMP/six-hypercube.json" ] && [ -f "$TMP/six-torus.json" ]; then
    check "6-cube: the torus's 384 links" test "$(json "$TMP/six-hypercube.json" .links.count)" = 384
    check "6-cube: the torus's packet hops" test "$(jq -s '.[0].links.packets == .[1].links.packets' \
        "$TMP/six-hypercube.json" "$TMP/six-torus.json")" = true
    check "6-cube: hops made" test "$(json "$TMP/six-hypercube.json" .links.packets)" -gt 0
fi

for m in cost scatter; do
    sim_ok "map-$m" "${common[@]}" --ips 2x2x2 --topology hypercube --map "$m" -o "$TMP/map-$m.png" \
        --stats "$TMP/map-$m.json" && image_and_packets "map-$m"
done

"$sim" "${common[@]}" --ips 2x4 --topology hypercube --route-ties plus -o "$TMP/s.png" >"$TMP/summary.txt" 2>&1
check "summary names the cube" grep -q "2x4x1 hypercube," "$TMP/summary.txt"
check "--route-ties is idle on a cube" grep -q "a hypercube has no way round" "$TMP/summary.txt"

bad_option --ips "6x4x4 cube" --ips 6x4x4 --topology hypercube
check "6x4x4: says why" grep -q "power of two" "$TMP/bad.stderr"
finish
