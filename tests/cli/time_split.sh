#!/usr/bin/env bash
# Where the time goes: for every processor the busy time by operation plus the idle time
# (starved, blocked, drained) adds up to the image time, on flat and clustered machines,
# approximately and loosely timed, with unbounded and bounded buffers. Every part is measured
# (none is the image time less the others): the sum is checked in whole picoseconds (one per
# part for rounding), each part is at least 0, the operations add up to the old per_ip busy_s,
# the machine's parts are the processors' sums, and a machine with buffers of one packet has
# blocked time. The summary gives the efficiency as work x balance x finish spread.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
f=$(source_scene paper-image1) || exit 1
runs=("flat-at --ips 2x2"
      "flat-at-queue1 --t1 1 --ips 2x2 --queue 1"
      "flat-lt --t1 1 --ips 2x2 --style lt --quantum 1ms"
      "flat-lt-queue1 --t1 1 --ips 2x2 --queue 1 --style lt --quantum 500us"
      "flat-none-queue200 --t1 1 --ips 2x2 --queue 200 --flow none"
      "cluster-shared --t1 1 --ips 2 --cluster 3 --data shared"
      "cluster-queue1 --t1 1 --ips 2 --cluster 2 --queue 1"
      "cluster-lt --t1 1 --ips 2 --cluster 2 --style lt --quantum 1ms")
for run in "${runs[@]}"; do
    set -- $run
    name=$1
    shift
    "$BUILD/torusrt-sim" "$f" --size 24x24 -o "$TMP/$name.png" --stats "$TMP/$name.json" "$@" \
        > "$TMP/$name.sum" 2> /dev/null || { fail "$name: run"; continue; }
    python3 - "$TMP/$name.json" > "$TMP/$name.bad" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
ps = lambda s: round(s * 1e12)
T, t = r["sim_time_s"], r["time"]
if len(t["per_ip"]) != r["ips"]:
    print("per_ip has %d entries for %d processors" % (len(t["per_ip"]), r["ips"]))
keys = ["starved_s", "blocked_s", "drained_s"]
for i, (p, old) in enumerate(zip(t["per_ip"], r["per_ip"])):
    parts = list(p["busy"].values()) + [p[k] for k in keys]
    if any(x < 0 for x in parts):
        print("ip %d: a negative part %s" % (i, p))
    total = sum(ps(x) for x in parts)
    if abs(total - ps(T)) > len(parts):
        print("ip %d: parts add up to %d ps, image time %d ps" % (i, total, ps(T)))
    if abs(sum(ps(x) for x in p["busy"].values()) - ps(old["busy_s"])) > len(p["busy"]):
        print("ip %d: busy parts %s against busy_s %s" % (i, p["busy"], old["busy_s"]))
    if abs(ps(p["busy_s"] + p["idle_s"]) - ps(T)) > len(parts):
        print("ip %d: busy_s + idle_s != image time" % i)
for k in keys + ["busy_s"]:
    if abs(ps(t[k]) - sum(ps(p[k]) for p in t["per_ip"])) > len(t["per_ip"]):
        print("machine %s is not the processors' sum" % k)
if abs(ps(t["processor_s"]) - ps(T * r["ips"])) > 1:
    print("processor_s is not n T(n)")
print("blocked %.9f" % t["blocked_s"], file=sys.stderr)
PY
    check "$name: every processor's parts add up to the image time $(tr '\n' ' ' < "$TMP/$name.bad")" \
        test ! -s "$TMP/$name.bad"
done
for name in flat-at-queue1 flat-lt-queue1 cluster-queue1; do
    check "$name: buffers of one packet block" jq -e '.time.blocked_s > 0' "$TMP/$name.json"
done
check "unbounded flat: nothing blocks" jq -e '.time.blocked_s == 0' "$TMP/flat-at.json"
check "shared data: the fetches' bus and memory waits are busy" jq -e '.time.busy.bus_memory_wait > 0' \
    "$TMP/cluster-shared.json"
check "flat: no bus or memory wait" jq -e '.time.busy.bus_memory_wait == 0' "$TMP/flat-at.json"
# The efficiency line's product: work x balance x finish spread is the efficiency.
check "efficiency factors printed" grep -qE '^ +\= work [0-9.]+ % x balance [0-9.]+ % x finish spread [0-9.]+ %' \
    "$TMP/flat-at.sum"
python3 - "$TMP/flat-at.json" "$TMP/flat-at.sum" > "$TMP/product.bad" <<'PY'
import json, re, sys
r = json.load(open(sys.argv[1]))
w, b, f = map(float, re.search(r"= work ([0-9.]+) % x balance ([0-9.]+) % x finish spread ([0-9.]+) %",
                               open(sys.argv[2]).read()).groups())
busy = [p["busy_s"] for p in r["per_ip"]]
n, mean = len(busy), sum(busy) / len(busy)
want = (100 * r["t1_s"] / (n * mean), 100 * mean / max(busy), 100 * max(busy) / r["sim_time_s"])
if any(abs(x - y) > 0.05 for x, y in zip((w, b, f), want)):
    print("printed %s, want %s" % ((w, b, f), want))
if abs(w * b * f / 1e4 - 100 * r["efficiency"]) > 0.2:
    print("the product %.2f is not the efficiency %.2f" % (w * b * f / 1e4, 100 * r["efficiency"]))
PY
check "the factors are the scaling study's and multiply to the efficiency $(cat "$TMP/product.bad")" \
    test ! -s "$TMP/product.bad"
check "time split line" grep -qE '^  time split   of n T\(n\) = [0-9.]+ processor-s: busy [0-9.]+ %, idle [0-9.]+ % = starved' \
    "$TMP/flat-at.sum"
finish
