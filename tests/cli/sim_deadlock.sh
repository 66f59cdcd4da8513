#!/usr/bin/env bash
# Finite queues, one outcome each:
# - a configuration that must deadlock: paper-image1 (two lights) on one IP with --queue 1 and
#   one packet class (--flow none). Each
#   hit on a sphere lit by both lights makes two shadow packets whose cells the IP owns itself;
#   the first fills its input queue, which only that IP drains, so the second can never enter.
#   The run must end with exit 3, the deadlock message naming the full queue, no image and no
#   trace, and its JSON (status "deadlock") naming the same full queue, at the stall's time.
# - configurations that must finish: a queue as large as the number of packets the unbounded run
#   creates can never be full, so no writer ever waits; the run must give the reference image,
#   the unbounded run's simulated time and no stall time.
# Never a hang (each run has a time limit).
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
time_limit 120

f="$SRC/scenes/paper-image1.nff"
"${run_limited[@]}" "$BUILD/torusrt-sim" "$f" -o "$TMP/dead.png" --stats "$TMP/dead.json" --vcd "$TMP/dead.vcd" \
    -q --t1 1 --size 16x16 --ips 1 --queue 1 --flow none 2>"$TMP/err"
rc=$?
d="$TMP/dead.json"
check "one IP, --queue 1: exit 3 (got $rc)" test "$rc" -eq 3
check "deadlock message" grep -q "deadlock: the network stalled" "$TMP/err"
check "the full queue is named" grep -q "full: top.ip_0.input (1/1), 1 writer(s) waiting" "$TMP/err"
check "no image after deadlock" test ! -e "$TMP/dead.png"
check "no VCD after deadlock" test ! -e "$TMP/dead.vcd"
check "no temporary file left" test -z "$(ls "$TMP" | grep '^dead' | grep -v '^dead.json$')"
check "the deadlock JSON is written" test -s "$d"
check "JSON status deadlock" test "$(json "$d" '.status')" = deadlock
check "JSON: the stall's time is after the start" jq -e '.deadlock.time_s > 0' "$d"
check "JSON: the stall's time is the message's" \
    grep -q "stalled at $(jq -r '.deadlock.time_s' "$d" | awk '{ printf "%.6f", $1 }') s" "$TMP/err"
check "JSON: sim_time_s is the stall's time" jq -e '.sim_time_s == .deadlock.time_s' "$d"
check "JSON: top.ip_0.input is full, with its writer waiting" \
    jq -e '[.deadlock.full_queues[] | select(.name == "top.ip_0.input" and .occupancy == .capacity and
            .capacity == 1 and .waiting_writers >= 1)] | length == 1' "$d"
check "JSON: every full queue is full in the queue list too" \
    jq -e '[.deadlock.full_queues[].name] - [.queues[] | select(.capacity > 0 and .occupancy >= .capacity) | .name] == []' "$d"
check "JSON: no queue holds more than its capacity" jq -e 'all(.queues[]; .occupancy <= .capacity and .high_water <= .capacity)' "$d"
check "JSON: no queue stalled longer than the run" jq -e '. as $r | all(.queues[]; .stalled_s >= 0 and .stalled_s <= $r.deadlock.time_s)' "$d"
check "JSON: packets not conserved (some are stuck)" jq -e '.packets.conserved == false' "$d"
check "JSON: no efficiency without an image time (null)" \
    jq -e 'has("efficiency") and .efficiency == null and .efficiency_t1 == null' "$d"

for scene in one-cell facing-mirrors paper-image2; do
  f="$SRC/scenes/$scene.nff"
  [ -f "$f" ] || { fail "missing $f"; continue; }
  "$BUILD/torusrt-render" "$f" -o "$TMP/ref.png" -q --size 32x32 || fail "$scene reference"
  "${run_limited[@]}" "$BUILD/torusrt-sim" "$f" -o "$TMP/free.png" --stats "$TMP/free.json" -q --t1 1 --size 32x32 \
      --ips 2x2x2 || { fail "$scene unbounded run"; continue; }
  cap=$(json "$TMP/free.json" '.packets.created.total')
  rm -f "$TMP/sim.png"
  "${run_limited[@]}" "$BUILD/torusrt-sim" "$f" -o "$TMP/sim.png" --stats "$TMP/sim.json" -q --t1 1 --size 32x32 \
      --ips 2x2x2 --queue "$cap" 2>"$TMP/err"
  rc=$?
  check "$scene --queue $cap (every packet fits): exit 0 (got $rc: $(head -n 1 "$TMP/err"))" test "$rc" -eq 0
  check "$scene --queue $cap: reference image" cmp -s "$TMP/ref.png" "$TMP/sim.png"
  check "$scene --queue $cap: the unbounded run's image time" \
      test "$(json "$TMP/sim.json" '.sim_time_s')" = "$(json "$TMP/free.json" '.sim_time_s')"
  check "$scene --queue $cap: status ok" test "$(json "$TMP/sim.json" '.status')" = ok
  check "$scene --queue $cap: no queue ever full, no stall" \
      jq -e --argjson c "$cap" 'all(.queues[]; .capacity == $c and .high_water < $c and .stalled_s == 0)' "$TMP/sim.json"
done
finish
