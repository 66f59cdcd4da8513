#!/usr/bin/env bash
# --route-ties end to end (paper-image1 at 32x32 on 4x2x2, whose y and z rings have two nodes):
# - split: the ym and zm links carry packets (JSON links.per_link), the image is
#   torusrt-render's and packets are conserved, on the flat torus, with finite buffers under flow
#   classes, loosely timed and with clusters;
# - plus: every ym and zm link carries no packet, and the y and z + links carry them all;
# - without --route-ties the rule is split;
# - both rules give the same image; split's busiest link is less used, and with slow links (where
#   the links bound the time) split finishes sooner; the same run twice gives the same time; the JSON and the summary name the rule; --dump-config writes it and a machine
#   file holding it gives the same image time;
# - a bad rule is refused (exit 2) naming --route-ties, with no output.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
time_limit 300
sim="$BUILD/torusrt-sim"
scene="$SRC/scenes/paper-image1.nff"
size=(--size 32x32)
render_ok ref "$scene" "$TMP/ref.png" "${size[@]}" || { finish; exit 1; }
common=("$scene" "${size[@]}" --t1 1 --ips 4x2x2)
# Packets over the links of one direction name, e.g. `dir_packets r.json ym`.
dir_packets() { jq --arg d "$2" '[.links.per_link[] | select(.dir == $d) | .packets] | add' "$1"; }

machines=(
    "split:--route-ties split"
    "split-q1:--route-ties split --queue 1"
    "split-lt:--route-ties split --style lt --quantum 1ms"
    "split-cluster:--route-ties split --cluster 4 --data shared --queue 2"
    "plus:--route-ties plus"
)
for m in "${machines[@]}"; do
    name=${m%%:*}
    read -r -a opts <<<"${m#*:}"
    if sim_ok "$name" "${common[@]}" "${opts[@]}" -o "$TMP/$name.png" --stats "$TMP/$name.json"; then
        check "$name: reference image" cmp -s "$TMP/ref.png" "$TMP/$name.png"
        check "$name: packets conserved" test "$(json "$TMP/$name.json" .packets.conserved)" = true
        check "$name: rule reported" test "$(json "$TMP/$name.json" .config.route_ties)" = "${name%%-*}"
        check "$name: capacity kept" test "$(json "$TMP/$name.json" \
            '.flow.capacity_packets == 0 or .flow.high_water <= .flow.capacity_packets')" = true
        for dir in ym zm; do
            n=$(dir_packets "$TMP/$name.json" "$dir")
            if [ "${name%%-*}" = split ]; then
                check "$name: the $dir links carry packets ($n)" test "$n" -gt 0
            else
                check "$name: the $dir links carry none ($n)" test "$n" -eq 0
            fi
        done
    fi
done
# The default rule is split: without --route-ties the ym and zm links carry packets.
if sim_ok default "${common[@]}" -o "$TMP/default.png" --stats "$TMP/default.json"; then
    check "default: the rule is split" test "$(json "$TMP/default.json" .config.route_ties)" = split
    for dir in ym zm; do
        check "default: the $dir links carry packets" test "$(dir_packets "$TMP/default.json" "$dir")" -gt 0
    done
fi
if [ -f "$TMP/split.json" ] && [ -f "$TMP/plus.json" ]; then
    check "plus: the yp links carry the y traffic of split" test "$(dir_packets "$TMP/plus.json" yp)" -gt 0
    check "split: the busiest link is less used than under plus" test "$(jq -s \
        '.[0].links.utilisation.max < .[1].links.utilisation.max' "$TMP/split.json" "$TMP/plus.json")" = true
fi
# With slow links (2 ms a packet) the y and z + links of plus saturate: split, with twice the
# links in its rings of two, finishes sooner.
for r in split plus; do
    sim_ok "slow-$r" "${common[@]}" --route-ties "$r" --link-us 2000 -o "$TMP/slow-$r.png" --stats "$TMP/slow-$r.json"
done
if [ -f "$TMP/slow-split.json" ] && [ -f "$TMP/slow-plus.json" ]; then
    check "slow links: split image time below plus's" test "$(jq -s '.[0].sim_time_s < .[1].sim_time_s' \
        "$TMP/slow-split.json" "$TMP/slow-plus.json")" = true
    check "slow links: split's image is the reference" cmp -s "$TMP/ref.png" "$TMP/slow-split.png"
fi
if sim_ok again "${common[@]}" --route-ties split -o "$TMP/again.png" --stats "$TMP/again.json"; then
    check "same image time twice" test "$(jq -s '.[0].sim_time_s == .[1].sim_time_s' \
        "$TMP/split.json" "$TMP/again.json")" = true
fi

"$sim" "${common[@]}" --route-ties split -o "$TMP/s.png" >"$TMP/summary.txt" 2>&1
check "summary names the rule" grep -q "4x2x2 torus (ties split)" "$TMP/summary.txt"

"$sim" --dump-config --ips 4x2x2 --route-ties split >"$TMP/m.toml" 2>"$TMP/dump.stderr"
check "dump-config writes the rule" grep -q '^route-ties="split"' "$TMP/m.toml"
if sim_ok file "${common[@]}" --config "$TMP/m.toml" -o "$TMP/file.png" --stats "$TMP/file.json"; then
    check "machine file: same image time" test "$(jq -s '.[0].sim_time_s == .[1].sim_time_s' \
        "$TMP/split.json" "$TMP/file.json")" = true
fi

bad_option --route-ties "bad rule" --route-ties minus
finish
