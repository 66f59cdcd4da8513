#!/usr/bin/env bash
# The balanced scatter end to end (--map scatter, with and without --replicate):
# - paper-image2 at 24x24 on 8x4x4 gives torusrt-render's image byte for byte, packets
#   conserved, the mapper reported as scatter, and the busiest node's predicted work within one
#   cell's work of the mean (what dealing the hottest cell first to the lightest node guarantees);
# - with --replicate 0.5 under both --replica-choice rules: the reference image, packets
#   conserved, cells cut over several owners, the predicted busiest node lighter than without
#   copies and the copies' bytes within the budget (half the memory without them, in all);
# - --write-map then --map-file gives the same image time; capacity 1 (--flow classes) with the
#   copies finishes with the reference image;
# - the same run twice gives the same table (the deal is deterministic);
# - --replicate and --pilot-size with another mapping are refused (exit 2) naming both mappings,
#   and so is --remap (it remaps with Scotch) with the scatter.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
time_limit 300
sim="$BUILD/torusrt-sim"
scene="$SRC/scenes/paper-image2.nff"
size=(--size 24x24)
render_ok ref "$scene" "$TMP/ref.png" "${size[@]}" || { finish; exit 1; }
common=("$scene" "${size[@]}" --ips 8x4x4 --t1 1)

if sim_ok plain "${common[@]}" --map scatter -o "$TMP/plain.png" --stats "$TMP/plain.json" \
    --write-map "$TMP/plain.map"; then
    check "scatter: reference image" cmp -s "$TMP/ref.png" "$TMP/plain.png"
    check "scatter: packets conserved" test "$(json "$TMP/plain.json" .packets.conserved)" = true
    check "scatter: mapper reported" test "$(json "$TMP/plain.json" .mapping.mapper)" = scatter
    check "scatter: kind reported" test "$(json "$TMP/plain.json" .mapping.kind)" = scatter
    check "scatter: busiest within one cell of the mean" test "$(json "$TMP/plain.json" \
        '.mapping.predicted_max_node_work_s <= .mapping.predicted_mean_node_work_s + .mapping.pilot_max_cell_work_s + 1e-9')" = true
    check "scatter: no copies" test "$(json "$TMP/plain.json" .replication.cells)" = 0
fi
if sim_ok again "${common[@]}" --map scatter -o "$TMP/again.png" --write-map "$TMP/again.map"; then
    check "scatter: same table twice" cmp -s "$TMP/plain.map" "$TMP/again.map"
fi
if sim_ok back "${common[@]}" --map-file "$TMP/plain.map" -o "$TMP/back.png" --stats "$TMP/back.json"; then
    check "map file: reference image" cmp -s "$TMP/ref.png" "$TMP/back.png"
    check "map file: same image time" test "$(jq -s '.[0].sim_time_s == .[1].sim_time_s' \
        "$TMP/plain.json" "$TMP/back.json")" = true
fi

for choice in hash nearest; do
    if sim_ok "r-$choice" "${common[@]}" --map scatter --replicate 0.5 --replica-choice "$choice" \
        -o "$TMP/$choice.png" --stats "$TMP/$choice.json" --write-map "$TMP/$choice.map"; then
        check "$choice: reference image" cmp -s "$TMP/ref.png" "$TMP/$choice.png"
        check "$choice: packets conserved" test "$(json "$TMP/$choice.json" .packets.conserved)" = true
        check "$choice: cells cut" test "$(json "$TMP/$choice.json" .replication.cells)" -gt 0
        check "$choice: busiest lighter with the pieces" test "$(json "$TMP/$choice.json" \
            '.mapping.predicted_max_node_work_s < .mapping.predicted_max_node_work_unreplicated_s')" = true
        check "$choice: copies within the budget" test "$(jq -s \
            '.[0].replication.bytes <= 0.5 * .[1].memory.total_bytes' "$TMP/$choice.json" "$TMP/plain.json")" = true
        check "$choice: map version 2" test "$(head -c 14 "$TMP/$choice.map")" = "torusrt-map 2 "
    fi
done
if sim_ok q1 "${common[@]}" --map-file "$TMP/hash.map" --replica-choice hash --queue 1 -o "$TMP/q1.png" \
    --stats "$TMP/q1.json"; then
    check "q1: reference image" cmp -s "$TMP/ref.png" "$TMP/q1.png"
    check "q1: packets conserved" test "$(json "$TMP/q1.json" .packets.conserved)" = true
    check "q1: within capacity" test "$(json "$TMP/q1.json" '.flow.high_water <= 1')" = true
fi

# --remap remaps with Scotch: refused with the scatter (exit 2, no output).
rm -rf "$TMP/out" && mkdir "$TMP/out"
"$sim" "$scene" "${size[@]}" --ips 8x4x4 --map scatter --orbit 90 --frames 2 --remap every-frame -q -o "$TMP/out/f_%d.png" \
    >/dev/null 2>"$TMP/remap.stderr"
rc=$?
check "scatter with --remap: exit 2 (got $rc)" test "$rc" = 2
check "scatter with --remap: message" grep -q -- "--map scatter: not with --remap" "$TMP/remap.stderr"
check "scatter with --remap: no output" test -z "$(ls "$TMP/out")"

for opt in "--replicate 0.5" "--pilot-size 12x12"; do
    rm -rf "$TMP/out" && mkdir "$TMP/out"
    # shellcheck disable=SC2086 # opt holds an option and its value
    "$sim" "${common[@]}" --map block $opt -q -o "$TMP/out/x.png" >/dev/null 2>"$TMP/bad.stderr"
    rc=$?
    check "$opt with block: exit 2 (got $rc)" test "$rc" = 2
    check "$opt with block: message ($(head -c 200 "$TMP/bad.stderr"))" grep -q -- "only with --map cost or scatter" \
        "$TMP/bad.stderr"
    check "$opt with block: no output" test -z "$(ls "$TMP/out")"
done
finish
