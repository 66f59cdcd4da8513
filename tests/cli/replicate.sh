#!/usr/bin/env bash
# Replicated cells end to end (--map cost --replicate, --replica-choice, torusrt-map 2):
# - paper-image2 at 24x24 on 2x2x2 with --map cost --replicate 0.5 gives torusrt-render's image
#   byte for byte under both --replica-choice rules, packets conserved, some cell replicated,
#   the copies' bytes reported and the memory above the same mapping's without copies;
# - --write-map writes torusrt-map 2; that file read back with --map-file gives the same image,
#   the same replication figures and, written again, the same file; without replication the
#   written table is version 1;
# - with buffers of capacity 1 (--flow classes, flat and clusters of 2) the replicated table
#   finishes with the reference image and packets conserved; --flow none, which is not
#   deadlock-free, stops there with exit 3 and no image;
# - --load-map marks the replicated cells (the picture differs from the one without copies);
# - an animation on a replicated table gives the renderer's frames; --remap with one is refused;
# - bad version 2 files exit 2 naming FILE:LINE, with no output.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
time_limit 300
sim="$BUILD/torusrt-sim"
scene="$SRC/scenes/paper-image2.nff"
size=(--size 24x24)
render_ok ref "$scene" "$TMP/ref.png" "${size[@]}" || { finish; exit 1; }

common=("$scene" "${size[@]}" --ips 2x2x2 --t1 1)
for choice in nearest hash; do
    if sim_ok "cost-$choice" "${common[@]}" --map cost --replicate 0.5 --replica-choice "$choice" \
        -o "$TMP/$choice.png" --stats "$TMP/$choice.json" --write-map "$TMP/$choice.map"; then
        check "$choice: reference image" cmp -s "$TMP/ref.png" "$TMP/$choice.png"
        check "$choice: packets conserved" test "$(json "$TMP/$choice.json" .packets.conserved)" = true
        check "$choice: cells replicated" test "$(json "$TMP/$choice.json" .replication.cells)" -gt 0
        check "$choice: copies at least the cells" test "$(json "$TMP/$choice.json" \
            '.replication.copies >= .replication.cells')" = true
        check "$choice: copy bytes" test "$(json "$TMP/$choice.json" .replication.bytes)" -gt 0
        check "$choice: rule reported" test "$(json "$TMP/$choice.json" .replication.choice)" = "$choice"
        check "$choice: map version 2" test "$(head -c 14 "$TMP/$choice.map")" = "torusrt-map 2 "
    fi
done

# The same cost mapping without copies: less memory, a version 1 table.
if sim_ok cost0 "${common[@]}" --map cost -o "$TMP/cost0.png" --stats "$TMP/cost0.json" --write-map "$TMP/cost0.map" \
    --load-map "$TMP/load0.png"; then
    check "no copies: version 1 table" test "$(head -c 14 "$TMP/cost0.map")" = "torusrt-map 1 "
    check "no copies: replication 0" test "$(json "$TMP/cost0.json" .replication.cells)" = 0
    check "copies cost memory" test "$(jq -s '.[0].memory.total_bytes > .[1].memory.total_bytes' \
        "$TMP/nearest.json" "$TMP/cost0.json")" = true
    check "same primary owners as without copies" cmp -s <(tail -n +3 "$TMP/cost0.map") \
        <(tail -n +3 "$TMP/nearest.map" | sed 's/,[0-9,]*//g')
fi

# Read back: the same image and figures, and the same table written again.
if sim_ok readback "${common[@]}" --map-file "$TMP/nearest.map" -o "$TMP/back.png" --stats "$TMP/back.json" \
    --write-map "$TMP/back.map" --load-map "$TMP/load.png"; then
    check "map file: reference image" cmp -s "$TMP/ref.png" "$TMP/back.png"
    check "map file: same table written again" cmp -s "$TMP/nearest.map" "$TMP/back.map"
    check "map file: same replication" test "$(jq -s 'map(.replication | del(.budget)) | .[0] == .[1]' \
        "$TMP/nearest.json" "$TMP/back.json")" = true
    check "map file: same image time" test "$(jq -s '.[0].sim_time_s == .[1].sim_time_s' \
        "$TMP/nearest.json" "$TMP/back.json")" = true
    check "load map marks the copies" bash -c "! cmp -s '$TMP/load.png' '$TMP/load0.png'"
fi

# Capacity 1: flow control with replicated cells.
for machine in "--ips 2x2x2 --map-file $TMP/nearest.map" "--ips 2x2x1 --cluster 2 --map cost --replicate 0.5"; do
    for choice in nearest hash; do
        name="q1 $machine $choice"
        # shellcheck disable=SC2086 # machine holds several words
        if sim_ok "q1" "$scene" "${size[@]}" $machine --t1 1 --queue 1 \
            --replica-choice "$choice" -o "$TMP/q1.png" --stats "$TMP/q1.json"; then
            check "$name: reference image" cmp -s "$TMP/ref.png" "$TMP/q1.png"
            check "$name: packets conserved" test "$(json "$TMP/q1.json" .packets.conserved)" = true
            check "$name: within capacity" test "$(json "$TMP/q1.json" '.flow.high_water <= 1')" = true
            check "$name: cells replicated" test "$(json "$TMP/q1.json" .replication.cells)" -gt 0
        fi
    done
done

# One class per buffer (--flow none) is not deadlock-free at capacity 1 (flow-control.md): with
# copies too such a run ends with exit 3 and no image rather than hanging.
rm -f "$TMP/none.png"
"${run_limited[@]}" "$sim" "${common[@]}" --map-file "$TMP/nearest.map" --queue 1 --flow none -q -o "$TMP/none.png" \
    >/dev/null 2>"$TMP/none.stderr"
rc=$?
check "flow none q1: exit 3 (got $rc)" test "$rc" = 3
check "flow none q1: no image" test ! -e "$TMP/none.png"

# An animation keeps a replicated table frame after frame (the renderer's frames); --remap
# would change the table, and is refused with one (exit 2, no output).
rm -rf "$TMP/anim" && mkdir "$TMP/anim"
anim=("$scene" "${size[@]}" --ips 2x2x2)
if sim_ok anim "${anim[@]}" --map-file "$TMP/nearest.map" --orbit 90 --frames 2 -o "$TMP/anim/f_%d.png" &&
    "$BUILD/torusrt-render" "$scene" -o "$TMP/anim/r_%d.png" -q "${size[@]}" --orbit 90 --frames 2; then
    check "animation: frame 0" cmp -s "$TMP/anim/r_0.png" "$TMP/anim/f_0.png"
    check "animation: frame 1" cmp -s "$TMP/anim/r_1.png" "$TMP/anim/f_1.png"
fi
rm -rf "$TMP/out" && mkdir "$TMP/out"
"$sim" "${anim[@]}" --map-file "$TMP/nearest.map" --orbit 90 --frames 2 --remap every-frame -q \
    -o "$TMP/out/f_%d.png" --stats "$TMP/out/s.json" >/dev/null 2>"$TMP/remap.stderr"
rc=$?
check "remap of a replicated table: exit 2 (got $rc)" test "$rc" = 2
check "remap of a replicated table: message" grep -q -- "--map-file: a table with replicated cells" "$TMP/remap.stderr"
check "remap of a replicated table: no output" test -z "$(ls "$TMP/out")"
rm -rf "$TMP/out" && mkdir "$TMP/out"
"$sim" "${anim[@]}" --map cost --replicate 0.5 --orbit 90 --frames 2 --remap every-frame -q \
    -o "$TMP/out/f_%d.png" --stats "$TMP/out/s.json" >/dev/null 2>"$TMP/remap.stderr"
rc=$?
check "--replicate with --remap: exit 2 (got $rc)" test "$rc" = 2
check "--replicate with --remap: message" grep -q -- "--replicate: not with --remap" "$TMP/remap.stderr"
check "--replicate with --remap: no output" test -z "$(ls "$TMP/out")"

# Bad version 2 files: FILE:LINE, exit 2, no output.
bad_map() {
    local what=$1 expect=$2
    printf '%b' "$3" > "$TMP/bad.map"
    rm -rf "$TMP/out" && mkdir "$TMP/out"
    "$sim" "${common[@]}" --map-file "$TMP/bad.map" -q -o "$TMP/out/x.png" --stats "$TMP/out/x.json" \
        >/dev/null 2>"$TMP/bad.stderr"
    local rc=$?
    check "$what: exit 2 (got $rc)" test "$rc" = 2
    check "$what: names $expect ($(head -c 200 "$TMP/bad.stderr"))" grep -q -- "$expect" "$TMP/bad.stderr"
    check "$what: no output" test -z "$(ls "$TMP/out")"
}
head -n 2 "$TMP/nearest.map" > "$TMP/head"
body=$(tail -n +3 "$TMP/nearest.map" | tr '\n' ' ')
first=${body%% *}
first=${first%%,*}
rest=${body#* }
bad_map "node twice" "bad.map:3: cell 0: node $first listed twice" "$(cat "$TMP/head")\n$first,$first $rest"
bad_map "empty item" "bad.map:3: cell 0: expected a node id" "$(cat "$TMP/head")\n$first, $rest"
bad_map "id out of range" "bad.map:3: cell 0: expected a node id 0..7" "$(cat "$TMP/head")\n$first,8 $rest"
bad_map "comma list in version 1" "bad.map:2: several owners" "torusrt-map 1 24 24 24 8\n$first,1 $rest"
finish
