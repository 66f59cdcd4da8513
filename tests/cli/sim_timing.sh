#!/usr/bin/env bash
# With one IP the simulated time is the sum of the kernel's op counts times the timing table,
# computed here from the reference renderer's counts; packets are conserved on every run;
# the same run twice gives identical images, times and per-IP statistics.
source "$(dirname "$0")/common.bash" "$@"
for scene in paper-image2 scale-1 facing-mirrors tir light-inside; do
  f="$SRC/scenes/$scene.nff"
  [ -f "$f" ] || { fail "missing scene $f"; continue; }
  size=(--size 40x40)
  "$BUILD/torusrt-render" "$f" -o "$TMP/r.png" --stats "$TMP/r.json" -q "${size[@]}" || { fail "$scene render"; continue; }
  "$BUILD/torusrt-sim" "$f" -o "$TMP/s.png" --stats "$TMP/s.json" -q "${size[@]}" --ips 1 --timing-profile literal || { fail "$scene sim"; continue; }
  expected=$(jq '.ops | .tests_missed*1300 + .tests_hit*1750 + .dda_steps*340 + .shadings*4600
                 + .reflection_vectors*680 + .refraction_vectors*1100 + .packets_analysed*580
                 + .packets_created*1600 + .handovers_sent*1600 + .handovers_received*580' "$TMP/r.json")
  got=$(jq '.sim_time_s * 1e6' "$TMP/s.json")
  check "$scene: one-IP time $got us equals sum of ops x table $expected us" \
    awk -v a="$got" -v b="$expected" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-6 * b + 1e-6) }'
  check "$scene: image" cmp -s "$TMP/r.png" "$TMP/s.png"
  check "$scene: conserved" test "$(json "$TMP/s.json" '.packets.conserved')" = true
  check "$scene: created = consumed" test "$(json "$TMP/s.json" '.packets.created.total')" = "$(json "$TMP/s.json" '.packets.consumed.total')"
  for run in a b; do
    "$BUILD/torusrt-sim" "$f" -o "$TMP/$run.png" --stats "$TMP/$run.json" -q "${size[@]}" --ips 4x2x2 --map block-cyclic:2 || fail "$scene 16 IPs"
    jq -c '[.sim_time_s, .efficiency_t1, .per_ip, .links.per_link]' "$TMP/$run.json" > "$TMP/$run.key"
  done
  check "$scene: deterministic image" cmp -s "$TMP/a.png" "$TMP/b.png"
  check "$scene: deterministic times and per-IP stats" cmp -s "$TMP/a.key" "$TMP/b.key"
  check "$scene: 16-IP image equals the reference" cmp -s "$TMP/r.png" "$TMP/a.png"
done
finish
