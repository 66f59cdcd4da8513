#!/usr/bin/env bash
# With one IP the simulated time is the sum of the kernel's op counts (the reference renderer's)
# times the timing table the run reports in its JSON (config.timing), with the paper's table and
# with a timing file of other figures (so the table really is read, not assumed); packets are
# conserved on every run;
# the same run twice gives identical images, times and per-IP statistics.
source "$(dirname "$0")/common.bash" "$@"
printf 'test_miss 1000\ntest_hit 2000\ndda_step 300\nshading 4000\nreflection 700\nrefraction 1200\npacket_analysis 500\npacket_creation 1500\nfb_write 7\nhandover_send 900\nhandover_receive 300\ncell_step_packet 250\n' >"$TMP/other.timing"
# expected_us RENDER.json SIM.json: the renderer's op counts times the simulator's config.timing.
expected_us() {
  jq -n --slurpfile r "$1" --slurpfile s "$2" '$r[0].ops as $o | $s[0].config.timing as $t
      | $o.tests_missed * $t.test_miss + $o.tests_hit * $t.test_hit + $o.dda_steps * $t.dda_step
      + $o.shadings * $t.shading + $o.reflection_vectors * $t.reflection + $o.refraction_vectors * $t.refraction
      + $o.packets_analysed * $t.packet_analysis + $o.packets_created * $t.packet_creation + $o.fb_writes * $t.fb_write
      + $o.handovers_sent * $t.handover_send + $o.handovers_received * $t.handover_receive
      + $o.cell_steps * $t.cell_step_packet'
}
near() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && b != "" && d <= 1e-6 * b + 1e-6) }'; }
for scene in paper-image2 scale-1 facing-mirrors tir light-inside; do
  f="$SRC/scenes/$scene.nff"
  [ -f "$f" ] || { fail "missing scene $f"; continue; }
  size=(--size 40x40)
  "$BUILD/torusrt-render" "$f" -o "$TMP/r.png" --stats "$TMP/r.json" -q "${size[@]}" || { fail "$scene render"; continue; }
  for timing in paper other; do
    topt=(); [ $timing = other ] && topt=(--timing "$TMP/other.timing")
    "$BUILD/torusrt-sim" "$f" -o "$TMP/s.png" --stats "$TMP/s.json" -q "${size[@]}" --ips 1 "${topt[@]}" \
      || { fail "$scene sim ($timing timing)"; continue; }
    expected=$(expected_us "$TMP/r.json" "$TMP/s.json")
    got=$(jq '.sim_time_s * 1e6' "$TMP/s.json")
    check "$scene ($timing timing): one-IP time $got us equals sum of ops x config.timing $expected us" near "$got" "$expected"
  done
  check "$scene: the timing file reached config.timing" test "$(json "$TMP/s.json" '.config.timing.fb_write')" = 7
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
