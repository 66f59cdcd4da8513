#!/usr/bin/env bash
# Deadlock-free flow control (--flow classes, the default) with small buffers:
# - every scene completes at --queue 1, 2, 4 and 8 with the reference renderer's image, at 8, 16
#   and 64 processors, flat and clustered, approximately and loosely timed (each scene gets one
#   point of that cross product per machine kind, chosen so every value of every axis is used);
# - no buffer holds more packets of one class than its capacity (the flow report, read with jq);
# - at capacity 1 the machine does the same work as unbounded (the same operation counts and
#   packets): flow control changes only the order of the work;
# - the same bounded run twice gives the same times;
# - --flow none on configurations known to deadlock (one class, capacity 1 or 2) exits 3 and
#   writes no image, and every full queue it names holds no more packets than its capacity (every
#   packet counts, primaries a cluster dispatcher handed to a processor too).
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
time_limit 120

queues=(1 2 4 8)
flat_ips=(2x2x2 4x2x2 4x4x4)   # 8, 16, 64 processors
clustered_ips=(2x2x1 2x2x2 4x4x2) # x 2 processors per node: 8, 16, 64
styles=("--style at" "--style lt --quantum 1ms")

# run_check NAME REF SCENE ARGS...: one run, its image and its flow report.
run_check() {
    local name=$1 ref=$2 f=$3
    shift 3
    rm -f "$TMP/sim.png"
    "${run_limited[@]}" "$BUILD/torusrt-sim" "$f" -o "$TMP/sim.png" --stats "$TMP/sim.json" -q --t1 1 --size 24x24 \
        "$@" 2>"$TMP/err"
    local rc=$?
    check "$name: exit 0 (got $rc: $(head -n 1 "$TMP/err"))" test "$rc" -eq 0
    [ "$rc" -eq 0 ] || return 1
    check "$name: reference image" cmp -s "$ref" "$TMP/sim.png"
    check "$name: packets conserved" test "$(json "$TMP/sim.json" '.packets.conserved')" = true
    check "$name: scheme classes" test "$(json "$TMP/sim.json" '.flow.scheme')" = classes
    check "$name: no buffer above its capacity" test "$(json "$TMP/sim.json" \
        '.flow.capacity_packets as $c | [.queues[] | select(.capacity != $c or .high_water > .capacity)] | length')" = 0
    check "$name: per-class high water within capacity" test "$(json "$TMP/sim.json" \
        '.flow.high_water <= .flow.capacity_packets and (.flow.class_high_water | max // 0) <= .flow.capacity_packets')" = true
    check "$name: classes within the bound" test "$(json "$TMP/sim.json" '.flow.classes_used <= .flow.classes_bound')" = true
}

i=0
for f in "$SRC"/scenes/*.nff; do
    scene=$(basename "$f" .nff)
    "$BUILD/torusrt-render" "$f" -o "$TMP/ref.png" -q --size 24x24 || { fail "$scene reference"; continue; }
    q=${queues[$((i % 4))]}
    style=${styles[$((i / 4 % 2))]}
    # shellcheck disable=SC2086 # style holds two options
    run_check "$scene flat ${flat_ips[$((i % 3))]} q$q $style" "$TMP/ref.png" "$f" --queue "$q" \
        --ips "${flat_ips[$((i % 3))]}" $style
    if [ "$q" = 1 ]; then
        cp "$TMP/sim.json" "$TMP/q1.json"
        # shellcheck disable=SC2086
        "${run_limited[@]}" "$BUILD/torusrt-sim" "$f" -o "$TMP/free.png" --stats "$TMP/free.json" -q --t1 1 \
            --size 24x24 --ips "${flat_ips[$((i % 3))]}" $style || fail "$scene unbounded"
        check "$scene q1: the same operations as unbounded" \
            test "$(jq -c .ops "$TMP/q1.json")" = "$(jq -c .ops "$TMP/free.json")"
        check "$scene q1: the same packets as unbounded" \
            test "$(jq -c .packets "$TMP/q1.json")" = "$(jq -c .packets "$TMP/free.json")"
    fi
    q=${queues[$(((i + 2) % 4))]}
    style=${styles[$(((i + 1) % 2))]}
    # shellcheck disable=SC2086
    run_check "$scene cluster 2 x ${clustered_ips[$(((i + 1) % 3))]} q$q $style" "$TMP/ref.png" "$f" --queue "$q" \
        --ips "${clustered_ips[$(((i + 1) % 3))]}" --cluster 2 $style
    i=$((i + 1))
done

# Deterministic: the same bounded run twice gives the same simulated time and delta cycles.
f="$SRC/scenes/paper-image2.nff"
for k in 1 2; do
    "${run_limited[@]}" "$BUILD/torusrt-sim" "$f" -o "$TMP/det$k.png" --stats "$TMP/det$k.json" -q --t1 1 --size 24x24 \
        --ips 2x2x2 --cluster 2 --dispatch shortest-queue --queue 1 --style lt --quantum 1ms || fail "determinism run $k"
done
check "bounded run twice: same time and delta cycles" \
    test "$(jq -c '[.sim_time_s, .delta_cycles]' "$TMP/det1.json")" = "$(jq -c '[.sim_time_s, .delta_cycles]' "$TMP/det2.json")"

f="$SRC/scenes/paper-image1.nff"
for cfg in "--ips 2x2x2 --queue 1" "--ips 4x2x2 --queue 2" "--ips 2x2x1 --cluster 2 --queue 1"; do
    rm -f "$TMP/dead.png"
    # shellcheck disable=SC2086
    "${run_limited[@]}" "$BUILD/torusrt-sim" "$f" -o "$TMP/dead.png" -q --t1 1 --size 24x24 $cfg --flow none \
        2>"$TMP/err"
    rc=$?
    check "--flow none $cfg: exit 3 (got $rc)" test "$rc" -eq 3
    check "--flow none $cfg: no image" test ! -e "$TMP/dead.png"
    check "--flow none $cfg: full queues named" grep -q "full: " "$TMP/err"
    check "--flow none $cfg: no queue above its capacity" test -z "$(sed -n 's/.*(\([0-9]*\)\/\([0-9]*\)).*/\1 \2/p' \
        "$TMP/err" | awk '$1 > $2')"
    # The same machine with the class scheme finishes.
    # shellcheck disable=SC2086
    "${run_limited[@]}" "$BUILD/torusrt-sim" "$f" -o "$TMP/live.png" -q --t1 1 --size 24x24 $cfg 2>"$TMP/err"
    check "--flow classes $cfg: exit 0" test $? -eq 0
done
finish
