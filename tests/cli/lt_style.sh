#!/usr/bin/env bash
# lt_style.sh - the loosely-timed style (--style lt --quantum Q) against the approximately-timed
# reference: the image never changes with the quantum (byte for byte); quantum 0 gives exactly the
# AT image time, efficiency and per-IP and per-link statistics; the timing error at the largest
# quantum tried is larger than at the smallest non-zero one; two LT runs give the same times. Also runs the quantum study script
# (experiments/error_vs_runtime/quantum.sh) on a small case and checks its CSV.
# Usage: bash lt_style.sh BUILD_DIR SOURCE_DIR
source "$(dirname "$0")/common.bash" "$@"

QUANTA=(0 100us 10ms 1s 100s)
# scene size torus
CASES=("paper-image2 48x48 4x2x2" "paper-image2 48x48 4x4x4" "facing-mirrors 40x40 2x2x2"
       "tir 40x40 4x2x2" "cones-and-patches 40x40 2x2x2")

# abs_err A B: |A - B| / B in per cent.
abs_err() { awk -v a="$1" -v b="$2" 'BEGIN { d = (a - b) / b * 100; if (d < 0) d = -d; printf "%.9g\n", d }'; }

for c in "${CASES[@]}"; do
  read -r scene size ips <<<"$c"
  f="$SRC/scenes/$scene.nff"
  tag="$scene $ips"
  [ -f "$f" ] || { fail "missing scene $f"; continue; }
  common=(-q --size "$size" --ips "$ips")
  "$BUILD/torusrt-sim" "$f" -o "$TMP/at.png" --stats "$TMP/at.json" "${common[@]}" || { fail "$tag: AT run"; continue; }
  t1=$(json "$TMP/at.json" .t1_s)
  at_time=$(json "$TMP/at.json" .sim_time_s)
  check "$tag: the AT run reports style at" test "$(json "$TMP/at.json" .config.style)" = at
  small_err="" large_err=""
  for q in "${QUANTA[@]}"; do
    out="$TMP/lt-$q"
    if ! "$BUILD/torusrt-sim" "$f" -o "$out.png" --stats "$out.json" "${common[@]}" --style lt --quantum "$q" --t1 "$t1"; then
      fail "$tag: LT run at quantum $q"
      continue
    fi
    check "$tag: LT image at quantum $q equals the AT image byte for byte" cmp -s "$TMP/at.png" "$out.png"
    check "$tag: LT run at quantum $q reports style lt" test "$(json "$out.json" .config.style)" = lt
    check "$tag: packets conserved at quantum $q" test "$(json "$out.json" .packets.conserved)" = true
    lt_time=$(json "$out.json" .sim_time_s)
    if [ "$q" = 0 ]; then
      # Exact: the same double, compared by jq, not as rounded text.
      check "$tag: quantum 0 sim_time_s $lt_time equals AT $at_time exactly" \
        jq -e --slurpfile a "$TMP/at.json" '.sim_time_s == $a[0].sim_time_s and .efficiency_busy == $a[0].efficiency_busy' "$out.json" >/dev/null
      check "$tag: quantum 0 per-IP and per-link statistics equal AT's" \
        jq -e --slurpfile a "$TMP/at.json" '.per_ip == $a[0].per_ip and .links.per_link == $a[0].links.per_link' "$out.json" >/dev/null
    else
      e=$(abs_err "$lt_time" "$at_time")
      [ -z "$small_err" ] && small_err=$e
      large_err=$e
    fi
  done
  if [ -n "$small_err" ] && [ -n "$large_err" ]; then
    check "$tag: |error| at ${QUANTA[-1]} ($large_err %) > at ${QUANTA[1]} ($small_err %)" \
      awk -v l="$large_err" -v s="$small_err" 'BEGIN { exit !(l > s) }'
  else
    fail "$tag: no errors to compare"
  fi
done

# Loosely timed with a quantum is deterministic too: packets routed within the quantum in one call
# chain, stamp-ordered queues and links booked by gaps give the same times run after run.
f="$SRC/scenes/paper-image2.nff"
for run in 1 2; do
  "$BUILD/torusrt-sim" "$f" -q --size 48x48 --ips 4x4x4 --style lt --quantum 1s --t1 1 -o "$TMP/det$run.png" \
    --stats "$TMP/det$run.json" || fail "determinism: LT run $run"
done
check "LT at 1 s: two runs give the same image" cmp -s "$TMP/det1.png" "$TMP/det2.png"
check "LT at 1 s: two runs give the same image time, per-IP and per-link statistics" \
  jq -e --slurpfile a "$TMP/det1.json" '.sim_time_s == $a[0].sim_time_s and .per_ip == $a[0].per_ip and .links.per_link == $a[0].links.per_link' \
  "$TMP/det2.json" >/dev/null

# The study script on a small case: every image equal, error 0 at quantum 0, larger at the end.
csv="$TMP/quantum.csv"
if bash "$SRC/experiments/error_vs_runtime/quantum.sh" --build "$BUILD" --out "$csv" --scenes paper-image2 \
     --ips 4x2x2 --size 48x48 --reps 1 --max-error 1000 --quanta "0 100us 10ms 1s 100s" 2>"$TMP/quantum.log"; then
  check "study: one AT row and five LT rows" test "$(awk -F, 'NR > 1 { n[$4]++ } END { print n["at"] + 0, n["lt"] + 0 }' "$csv")" = "1 5"
  check "study: every image equal to AT" test "$(awk -F, 'NR > 1 && $21 != "true"' "$csv" | wc -l)" -eq 0
  check "study: error 0 at quantum 0" awk -F, '$4 == "lt" && $5 == "0" { found = 1; if ($10 != 0 || $11 != 0) bad = 1 }
                                              END { exit !(found && !bad) }' "$csv"
  check "study: |error| at the largest quantum > at the smallest non-zero" awk -F, '
      function abs(x) { return x < 0 ? -x : x }
      $4 == "lt" && $6 > 0 { if (first == "") first = abs($10); last = abs($10) }
      END { exit !(first != "" && last > first) }' "$csv"
else
  fail "study: quantum.sh failed: $(tail -n 3 "$TMP/quantum.log")"
fi
finish
