#!/usr/bin/env bash
# --cost-image (torusrt-render) and --load-map (torusrt-sim) write valid PNGs; the cost
# image's per-pixel microseconds sum to the run's op-count total T(1) (integer-valued table:
# exactly), under both profiles; bad output folders are rejected with no output.
source "$(dirname "$0")/common.bash" "$@"
jq_true() { jq -e "$@" >/dev/null; }
need_exe torusrt-sim torusrt-render
for scene in paper-image1 paper-image2 tir; do
  f=$(source_scene $scene) || exit 1
  for profile in calibrated literal; do
    "$BUILD/torusrt-render" "$f" -o "$TMP/r.png" --stats "$TMP/r.json" -q --size 40x30 --timing-profile "$profile" \
      --cost-image "$TMP/cost.png" || { fail "$scene: render"; continue; }
    check "$scene $profile: cost image is a PNG" sh -c "file '$TMP/cost.png' | grep -q 'PNG image data'"
    total=$(json "$TMP/r.json" .cost_image.total_us); t1=$(jq '.t1_s * 1e6 | round' "$TMP/r.json")
    check "$scene $profile: cost image total $total us = T(1) $t1 us" jq_true '(.cost_image.total_us - .t1_s * 1e6 | fabs) < 1e-3' "$TMP/r.json"
    check "$scene $profile: a pixel costs something" jq_true '.cost_image.max_pixel_us > 0' "$TMP/r.json"
    expected=$(jq '.ops | .tests_missed*1300 + .tests_hit*1750 + .dda_steps*340 + .shadings*4600
                 + .reflection_vectors*680 + .refraction_vectors*1100 + .packets_analysed*580
                 + .packets_created*1600' "$TMP/r.json")
    check "$scene $profile: total equals the hand count of the ops ($expected)" test "$(jq '.cost_image.total_us' "$TMP/r.json")" = "$expected"
  done
  "$BUILD/torusrt-render" "$f" -o "$TMP/plain.png" -q --size 40x30
  check "$scene: the cost image leaves the render alone" cmp -s "$TMP/plain.png" "$TMP/r.png"
  for map in cyclic cost; do
    "$BUILD/torusrt-sim" "$f" -o "$TMP/s.png" -q --size 40x30 --ips 2x2x2 --map "$map" --cluster 2 \
      --load-map "$TMP/load.png" || { fail "$scene $map: sim"; continue; }
    check "$scene $map: load map is a PNG" sh -c "file '$TMP/load.png' | grep -q 'PNG image data'"
    check "$scene $map: image unchanged" cmp -s "$TMP/plain.png" "$TMP/s.png"
  done
done
f=$(source_scene paper-image1)
"$BUILD/torusrt-render" "$f" -o "$TMP/x.png" -q --size 8x8 --cost-image "$TMP/no/such/c.png" 2>/dev/null
check "--cost-image in a missing folder: exit 2" test $? -eq 2
check "--cost-image in a missing folder: no image" test ! -e "$TMP/x.png"
"$BUILD/torusrt-sim" "$f" -o "$TMP/y.png" -q --size 8x8 --load-map "$TMP/no/such/l.png" 2>/dev/null
check "--load-map in a missing folder: exit 2" test $? -eq 2
check "--load-map in a missing folder: no image" test ! -e "$TMP/y.png"
finish
