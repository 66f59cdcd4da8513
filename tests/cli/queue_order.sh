#!/usr/bin/env bash
# --queue-order rays-first end to end (paper-image1 at 24x24):
# - on every kind of machine (flat torus with unbounded buffers, capacity 1 under flow classes,
#   --flow none, a mesh, loosely timed, clusters with replicated and shared data, the scatter
#   with cut cells under the hash rule) it gives torusrt-render's image byte for byte, with
#   packets conserved and the capacity kept;
# - the same run twice gives the same image time; the order changes the image time against
#   primaries-first on 4x4x4;
# - the JSON and the summary name the order; --dump-config writes it and a machine file holding
#   it gives the same image time;
# - a bad order is refused (exit 2) naming --queue-order, with no output.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
time_limit 300
sim="$BUILD/torusrt-sim"
scene="$SRC/scenes/paper-image1.nff"
size=(--size 24x24)
render_ok ref "$scene" "$TMP/ref.png" "${size[@]}" || { finish; exit 1; }
common=("$scene" "${size[@]}" --t1 1 --queue-order rays-first)

machines=(
    "flat:--ips 4x4x4"
    "q1:--ips 4x4x4 --queue 1"
    "none:--ips 4x4x2 --flow none"
    "mesh:--ips 4x4x2 --topology mesh --queue 2"
    "lt:--ips 4x4x2 --style lt --quantum 1ms"
    "cluster:--ips 2x2x2 --cluster 4 --queue 2"
    "shared:--ips 2x2x2 --cluster 4 --data shared"
    "scatter:--ips 4x4x4 --map scatter --replicate 0.5 --replica-choice hash --queue 1"
)
for m in "${machines[@]}"; do
    name=${m%%:*}
    read -r -a opts <<<"${m#*:}"
    if sim_ok "$name" "${common[@]}" "${opts[@]}" -o "$TMP/$name.png" --stats "$TMP/$name.json"; then
        check "$name: reference image" cmp -s "$TMP/ref.png" "$TMP/$name.png"
        check "$name: packets conserved" test "$(json "$TMP/$name.json" .packets.conserved)" = true
        check "$name: order reported" test "$(json "$TMP/$name.json" .config.queue_order)" = rays-first
        check "$name: capacity kept" test "$(json "$TMP/$name.json" \
            '.flow.capacity_packets == 0 or .flow.high_water <= .flow.capacity_packets')" = true
    fi
done

if sim_ok again "${common[@]}" --ips 4x4x4 -o "$TMP/again.png" --stats "$TMP/again.json"; then
    check "same image time twice" test "$(jq -s '.[0].sim_time_s == .[1].sim_time_s' \
        "$TMP/flat.json" "$TMP/again.json")" = true
    check "same image twice" cmp -s "$TMP/flat.png" "$TMP/again.png"
fi
if sim_ok fifo "$scene" "${size[@]}" --t1 1 --ips 4x4x4 -o "$TMP/fifo.png" --stats "$TMP/fifo.json"; then
    check "default order reported" test "$(json "$TMP/fifo.json" .config.queue_order)" = primaries-first
    check "the order changes the image time" test "$(jq -s '.[0].sim_time_s != .[1].sim_time_s' \
        "$TMP/flat.json" "$TMP/fifo.json")" = true
fi

"$sim" "${common[@]}" --ips 4x4x4 -o "$TMP/s.png" >"$TMP/summary.txt" 2>&1
check "summary names the order" grep -q "queue order rays-first" "$TMP/summary.txt"

"$sim" --dump-config --ips 4x4x4 --queue-order rays-first >"$TMP/m.toml" 2>"$TMP/dump.stderr"
check "dump-config writes the order" grep -q '^queue-order="rays-first"' "$TMP/m.toml"
if sim_ok file "$scene" "${size[@]}" --t1 1 --config "$TMP/m.toml" -o "$TMP/file.png" --stats "$TMP/file.json"; then
    check "machine file: same image time" test "$(jq -s '.[0].sim_time_s == .[1].sim_time_s' \
        "$TMP/flat.json" "$TMP/file.json")" = true
fi

bad_option --queue-order "bad order" --queue-order newest
finish
