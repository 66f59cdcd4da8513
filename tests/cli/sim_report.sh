#!/usr/bin/env bash
# The summary and the JSON come from one report, and the queue figures mean what they say:
# - the summary's image time, efficiency, packet hops, wall times and queue line equal the JSON's,
#   and the elaboration's and the simulation's wall times are parts of the run's;
# - every queue of the flat torus is listed once (an input queue per IP, one per link), with the
#   high water the per-IP and per-link entries give, and with unbounded queues no writer ever
#   waits (stalled_s 0, nothing ever full);
# - with every queue one packet smaller than the unbounded run's largest high water, the run is
#   the unbounded one until that queue is full, so a writer must wait for its reader to take a
#   packet: a completed run with stall time > 0 and no queue above its capacity.
# These figures are those of one class per buffer (--flow none), where a queue's high water is
# the per-IP and per-link one; under the default class split (--flow classes) a queue's high
# water is that of its fullest class buffer, and with one slot per class buffer writers wait.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
time_limit 300

f="$SRC/scenes/paper-image2.nff"
opts=(-o "$TMP/a.png" --t1 1 --size 32x32 --ips 2x2x2 --flow none)
"${run_limited[@]}" "$BUILD/torusrt-sim" "$f" "${opts[@]}" --stats "$TMP/a.json" >"$TMP/sum" || fail "unbounded run"
j="$TMP/a.json"
line() { grep "^  $1 " "$TMP/sum"; }
six() { awk '{ printf "%.6f", $1 }'; }
# The summary's figures: 4 significant digits, no exponent.
sig4() { python3 -c 'import math, sys; v = float(sys.argv[1]); d = 3 - math.floor(math.log10(abs(v))) if v else 0; print("%.*f" % (max(d, 0), v))' "$(cat)"; }
check "status ok" test "$(json "$j" '.status')" = ok
# The first line counts the scene's objects and lights in words that agree with the counts.
check "summary: objects and lights counted as the JSON has them" \
    test "$(head -n 1 "$TMP/sum" | sed 's/.*(32x32, //')" = \
    "$(json "$j" '"\(.objects) object\(if .objects == 1 then "" else "s" end), \(.lights) light\(if .lights == 1 then "" else "s" end))"')"
printf 'v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 30\nhither 0.01\nresolution 8 8\nl 1 1 5\nf 1 1 1 1 0 0 0 1\ns 0 0 0 1\n' >"$TMP/one.nff"
"${run_limited[@]}" "$BUILD/torusrt-sim" "$TMP/one.nff" -o "$TMP/one.png" --t1 1 >"$TMP/one.sum" || fail "one-light run"
check "summary: one object and one light in the singular" grep -q '(8x8, 1 object, 1 light)' "$TMP/one.sum"
check "summary image time = sim_time_s" \
    test "$(line 'image time' | awk '{ print $3 }')" = "$(json "$j" '.sim_time_s' | sig4)"
check "summary efficiency = efficiency" \
    test "$(line efficiency | awk '{ print $2 }')" = "$(json "$j" '.efficiency * 100' | awk '{ printf "%.1f", $1 }')"
check "summary packet hops = links.packets" \
    test "$(line links | awk '{ print $4 }')" = "$(json "$j" '.links.packets')"
check "wall: elaboration and simulation are parts of the whole run" \
    jq -e '.elaboration_wall_s > 0 and .sim_wall_s > 0 and .elaboration_wall_s + .sim_wall_s <= .wall_s' "$j"
check "summary wall line = wall_s, elaboration_wall_s, sim_wall_s" \
    test "$(line wall | awk '{ print $2, $4, $7 }' | tr -d '(')" = \
    "$(json "$j" '"\(.wall_s) \(.elaboration_wall_s) \(.sim_wall_s)"' | awk '{ printf "%.3f %.3f %.3f", $1, $2, $3 }')"
hw=$(json "$j" '[.queues[].high_water] | max')
name=$(json "$j" "[.queues[] | select(.high_water == $hw)][0].name")
check "summary: largest high water $hw ($name)" \
    grep -q "^  queues       $(json "$j" '.queues | length'), largest high water $hw ($name, capacity unbounded)" "$TMP/sum"
check "summary: no writer waited" grep -q "capacity unbounded), no writer waited for room$" "$TMP/sum"
check "one queue per IP and per link" \
    jq -e '(.queues | length) == (.per_ip | length) + .links.count and ([.queues[].name] | unique | length) == (.queues | length)' "$j"
check "IP input queues: the per-IP high water" \
    jq -e '. as $r | all($r.per_ip[]; .id as $i | .queue_high_water as $h |
           ($r.queues[] | select(.name == "top.ip_\($i).input") | .high_water) == $h)' "$j"
check "links: the per-link high water" \
    jq -e '[.links.per_link[].queue_high_water] == [.queues[] | select(.name | startswith("top.link_")) | .high_water]' "$j"
check "unbounded: capacity 0, no stall, nobody waiting, nothing left" \
    jq -e 'all(.queues[]; .capacity == 0 and .stalled_s == 0 and .waiting_writers == 0 and .occupancy == 0)' "$j"

q=$((hw - 1))
"${run_limited[@]}" "$BUILD/torusrt-sim" "$f" "${opts[@]}" --stats "$TMP/b.json" --queue "$q" >"$TMP/sum_b"
rc=$?
b="$TMP/b.json"
check "--queue $q: completes (exit $rc)" test "$rc" -eq 0
check "--queue $q: status ok" test "$(json "$b" '.status')" = ok
check "--queue $q: some writer waited (stalled_s > 0)" jq -e '[.queues[].stalled_s] | max > 0' "$b"
check "--queue $q: no queue above its capacity" jq -e "all(.queues[]; .capacity == $q and .high_water <= $q)" "$b"
check "--queue $q: nobody left waiting" jq -e 'all(.queues[]; .waiting_writers == 0 and .occupancy == 0)' "$b"
worst=$(json "$b" '([.queues[].stalled_s] | max) as $m | [.queues[] | select(.stalled_s == $m)][0].name')
check "--queue $q: summary names the longest-stalled queue ($worst) and its stall" \
    grep -q "writers waited for room: $worst, the longest-stalled queue, $(json "$b" '[.queues[].stalled_s] | max' | sig4) s;" "$TMP/sum_b"
share=$(sed -n 's/.*some writer waited \([0-9.]*\) % of the image time$/\1/p' "$TMP/sum_b")
check "--queue $q: the share of the image time any writer waited ($share %) is at least the longest-stalled queue's" \
    python3 -c 'import sys; s, m, t = map(float, sys.argv[1:]); sys.exit(not (100 * m / t * 0.999 <= s <= 100.0001))' \
    "${share:-nan}" "$(json "$b" '[.queues[].stalled_s] | max')" "$(json "$b" '.sim_time_s')"

"${run_limited[@]}" "$BUILD/torusrt-sim" "$f" -o "$TMP/c.png" --t1 1 --size 32x32 --ips 2x2x2 --queue 1 \
    --stats "$TMP/c.json" -q
check "--flow classes --queue 1: completes" test "$?" -eq 0
c="$TMP/c.json"
check "--flow classes --queue 1: some writer waited" jq -e '[.queues[].stalled_s] | max > 0' "$c"
check "--flow classes --queue 1: a stall is no longer than the run" \
    jq -e '.sim_time_s as $t | all(.queues[]; .stalled_s >= 0 and .stalled_s <= $t)' "$c"
check "--flow classes --queue 1: no class buffer above one packet, several classes used" \
    jq -e 'all(.queues[]; .capacity == 1 and .high_water <= 1) and ([.queues[].buffers_used] | max > 1)' "$c"
finish
