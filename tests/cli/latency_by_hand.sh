#!/usr/bin/env bash
# Packet and pixel latency on a case worked by hand: one pixel, two IPs (--ips 2), two cells
# along x (cell 0 owned by IP 0, cell 1 by IP 1), the calibrated profile (hand-overs and cell
# steps cost nothing beyond the link, a link takes 50 us a packet). The primary ray runs along +x; sphere A, off
# the axis, lies in cell 0; sphere B, on the axis, in cell 1; one light, behind the camera and
# above the scene's thin slab in z, so the shadow packet leaves the object space in cell 1.
#
# IP 0, 0-2220 us: the primary's analysis 580 + its start cell 340 + a miss on A 1300; the next
#   cell is IP 1's: handed over at 2220 (a cell step, no cost), over link 0->1 xp, 2220-2270.
# IP 1, 2270-10560 us: a hit on B 1750 + shading 4600 + the shadow packet's creation 1600 + its
#   start cell 340 = 8290; the primary is consumed at 10560.
# IP 1, 10560-12780 us: the shadow's analysis 580 + a miss on B (its own surface) 1300 + the
#   next-cell determination that leaves the object space 340 = 2220; it contributes to the
#   pixel and is consumed at 12780 us, the image time.
#
# Primary: latency 10560 us = processing 2220 + 8290 = 10510, links 50 (one hop), queued 0.
# Shadow: made at 10560, taken up at once: latency 2220 = processing 2220, no hop, queued 0.
# Pixel: its primary's first step starts at 0, its last contribution at 12780: 12780 us.
# Time split: IP 0 busy 2220, starved 0 (the primary is there at 0), drained 12780 - 2220 =
# 10560; IP 1 starved 2270 (until the primary arrives), busy 8290 + 2220 = 10510, drained 0.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
sim="$BUILD/torusrt-sim"
cat > "$TMP/one.nff" <<'NFF'
v
from -10 0 0
at 0 0 0
up 0 1 0
angle 10
hither 0.001
resolution 1 1
b 0.1 0.1 0.1
l -20 0 5
f 0.8 0.5 0.3 0.7 0 0 0 1
s -3 2 0 0.5
s 3 0 0 0.5
NFF
render_ok ref "$TMP/one.nff" "$TMP/ref.png" || { finish; exit 1; }
sim_ok run "$TMP/one.nff" --ips 2 --cells 2x1x1 --timing-profile calibrated --t1 1 -o "$TMP/o.png" --stats "$TMP/o.json" ||
    { finish; exit 1; }
"$BUILD/torusrt-sim" "$TMP/one.nff" --ips 2 --cells 2x1x1 --timing-profile calibrated --t1 1 -o "$TMP/s.png" > "$TMP/sum" \
    2> /dev/null
check "the renderer's image" cmp -s "$TMP/ref.png" "$TMP/o.png"
# is PATH VALUE: the JSON's number at PATH equals VALUE (to a picosecond, in us or s).
is() {
    local got
    got=$(jq "$1" "$TMP/o.json")
    check "$1 = $2 (got $got)" awk -v a="$got" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d < 1e-6) }'
}
is .sim_time_s 0.01278
P=.latency.packets
for k in count mean_us p50_us p95_us p99_us max_us; do
    want=10560; [ $k = count ] && want=1
    is "$P.primary.$k" "$want"
done
is "$P.primary.processing_us.mean" 10510
is "$P.primary.links_us.mean" 50
is "$P.primary.queued_us.mean" 0
is "$P.primary.hops.mean" 1
is "$P.primary.hops.max" 1
for k in mean_us p50_us p99_us max_us processing_us.mean; do is "$P.shadow.$k" 2220; done
is "$P.shadow.count" 1
is "$P.shadow.links_us.mean" 0
is "$P.shadow.queued_us.mean" 0
is "$P.shadow.hops.max" 0
is "$P.ray.count" 0
check "primary histogram: one packet in [8192, 16384) us" \
    test "$(jq -c "$P.primary.histogram" "$TMP/o.json")" = '[{"count":1,"from_us":8192,"to_us":16384}]'
check "shadow histogram: one packet in [2048, 4096) us" \
    test "$(jq -c "$P.shadow.histogram" "$TMP/o.json")" = '[{"count":1,"from_us":2048,"to_us":4096}]'
for k in count mean_us p50_us p95_us max_us; do
    want=12780; [ $k = count ] && want=1
    is ".latency.pixels.$k" "$want"
done
T=.time.per_ip
is "$T[0].busy_s" 0.00222
is "$T[0].starved_s" 0
is "$T[0].blocked_s" 0
is "$T[0].drained_s" 0.01056
is "$T[1].busy_s" 0.01051
is "$T[1].starved_s" 0.00227
is "$T[1].drained_s" 0
is "$T[1].busy.shading" 0.0046
is "$T[0].busy.test_miss" 0.0013
check "summary: the busiest link named" grep -qF "busiest links (from->to direction use): 0->1 xp" "$TMP/sum"
check "summary: primary latency" \
    grep -qF "latency      primary mean 10.56 p95 10.56 max 10.56 ms (queued 0, links 0.05000, processing 10.51), hops 1.000" \
    "$TMP/sum"
check "summary: pixel latency" grep -qF "pixel mean 12.78 p50 12.78 p95 12.78 max 12.78 ms" "$TMP/sum"
finish
