#!/usr/bin/env bash
# Shared data can finish before replicated data: a list-scheduling effect of the round-robin
# dispatcher (docs/cluster.md, "Shared against replicated data"), on a case small enough to work
# by hand. Three pixels, eight spheres, one node of two processors (--ips 1 --cluster 2), three
# cells along x, round one's profile named explicitly (--timing-profile round-one: a 2 us bus
# cycle and memory access, nothing charged per cell step), on which every figure below relies.
# Objects are dealt by index to the node's processors (even to 0, odd to 1); spheres 1 and 3 lie
# in the left cell, 5 and 7 in the centre cell, all four held by processor 1; the others lie in
# the right cell, off every ray's path but the right pixel's.
#
# Step work (us): P0 and P1, the left and centre primaries: a miss 1300 + a hit 1750 + shading
# 4600 + one shadow packet 1600 + analysis 580 + the shadow's start cell 340 = 10170; P2, the
# right primary: 4 misses = 6120 (with its analysis and DDA steps); shadow A (from P0) 3520,
# shadow B (from P1) 6460. A packet over the bus takes 28.25 us, an object read 22.25 us
# (round-one; the default profile, fitted, makes them 56.25 and 40.75 us).
# The round-robin dispatcher sends P0 to processor 0, P1 to 1, P2 to 0, then the next packet to 1.
#
# Replicated: P0 ends at 10198.25 us, P1 at 10226.5, so A reaches the dispatcher first and goes
# to processor 1, B to processor 0 behind P2: P2 runs 10226.5-16346.5, B to 22806.5 us.
# Shared: processor 0 reads spheres 1 and 3 from processor 1 over the bus, behind the
# dispatcher's writes of P1 and P2, so P0 ends at 10299.25, after P1 (10226.5; its spheres 5
# and 7 are its own). B arrives first and goes to the idle processor 1 (10283-16743); A goes
# behind P2 on processor 0 (P2 10327.5-16447.5, then A with 44.5 us of reads) to 20012 us.
# Shared does 145.5 us more work (reads and bus waits) and finishes 2794.5 us earlier.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
sim="$BUILD/torusrt-sim"
cat >"$TMP/swap.nff" <<'NFF'
v
from 0 0 10
at 0 0 0
up 0 1 0
angle 30
hither 0.001
resolution 3 1
b 0.1 0.1 0.1
l -20 0 3
f 0.8 0.5 0.3 0.7 0 0 0 1
s 3.8 1.5 0 0.7
s -2.2 0 0 0.6
s 2.6 -1.5 2.0 0.7
s -3.8 1.5 0 0.7
s 2.6 1.5 -2.0 0.7
s 0 0 0 0.6
s 3.8 -1.5 -1.5 0.7
s 0 1.5 0 0.7
NFF
render_ok ref "$TMP/swap.nff" "$TMP/ref.png" || { finish; exit 1; }
machine=(--ips 1 --cluster 2 --cells 3x1x1 --timing-profile round-one --dispatch round-robin --t1 1)
# near A B: |A - B| < 1e-9 (seconds).
near() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d < 1e-9) }'; }
for data in replicated shared; do
    if sim_ok "$data" "$TMP/swap.nff" "${machine[@]}" --data "$data" -o "$TMP/$data.png" --stats "$TMP/$data.json"; then
        check "$data: the renderer's image" cmp -s "$TMP/ref.png" "$TMP/$data.png"
        check "$data: packets conserved" test "$(json "$TMP/$data.json" .packets.conserved)" = true
    fi
done
[ -f "$TMP/replicated.json" ] && [ -f "$TMP/shared.json" ] || { finish; exit 1; }
t_r=$(json "$TMP/replicated.json" .sim_time_s) t_s=$(json "$TMP/shared.json" .sim_time_s)
check "replicated ends at 22806.5 us (got $t_r s)" near "$t_r" 0.0228065
check "shared ends at 20012 us (got $t_s s)" near "$t_s" 0.020012
busy() { jq '[.per_ip[].busy_s] | add' "$1"; }
check "replicated busy = the steps' work, 36440 us" near "$(busy "$TMP/replicated.json")" 0.03644
check "shared busy = 36440 us + 145.5 us of reads and bus waits" near "$(busy "$TMP/shared.json")" 0.0365855
check "replicated per processor: 22750 and 13690 us" test "$(jq -c '[.per_ip[].busy_s * 1e6 | round]' \
    "$TMP/replicated.json")" = "[22750,13690]"
check "shared per processor: 19955.5 and 16630 us" test "$(jq -c '[.per_ip[].busy_s * 1e7 | round]' \
    "$TMP/shared.json")" = "[199555,166300]"
check "shared reads four objects over the bus" test "$(json "$TMP/shared.json" .bus.object_reads)" = 4
check "the same operations in both" test "$(jq -s '.[0].ops == .[1].ops' "$TMP/replicated.json" "$TMP/shared.json")" = true
finish
