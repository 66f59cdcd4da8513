#!/usr/bin/env bash
# On paper-image1 at 16 IPs (4x2x2 torus): the cyclic (load-balancing) mapping beats block
# mapping in load balance (busy / (n T(n))) under the literal timing profile, and in the
# headline efficiency T(1) / (n T(n)) and image time under the default (fitted) profile;
# the data memory requirement is well below the pixel-partitioned figure.
source "$(dirname "$0")/common.bash" "$@"
f="$SRC/scenes/paper-image1.nff"
for map in block cyclic; do
  "$BUILD/torusrt-sim" "$f" -o "$TMP/$map.png" --stats "$TMP/$map.json" -q --ips 4x2x2 --map "$map" --t1 1 \
    --timing-profile literal || fail "run $map"
  "$BUILD/torusrt-sim" "$f" -o "$TMP/$map-cal.png" --stats "$TMP/$map-cal.json" -q --ips 4x2x2 --map "$map" \
    || fail "run $map default profile"
done
eb=$(json "$TMP/block.json" .load_balance); ec=$(json "$TMP/cyclic.json" .load_balance)
echo "literal load_balance: block $eb, cyclic $ec"
check "literal: cyclic ($ec) beats block ($eb) in load balance" awk -v c="$ec" -v b="$eb" 'BEGIN { exit !(c > b) }'
check "efficiency_busy is load_balance" test "$(json "$TMP/block.json" .efficiency_busy)" = "$eb"
eb=$(json "$TMP/block-cal.json" .efficiency); ec=$(json "$TMP/cyclic-cal.json" .efficiency)
echo "default profile's efficiency: block $eb, cyclic $ec"
check "default profile: cyclic ($ec) beats block ($eb) in efficiency" awk -v c="$ec" -v b="$eb" 'BEGIN { exit !(c > b) }'
check "default profile: cyclic image time shorter" awk -v c="$(json "$TMP/cyclic-cal.json" .sim_time_s)" \
  -v b="$(json "$TMP/block-cal.json" .sim_time_s)" 'BEGIN { exit !(c < b) }'
check "efficiency_t1 is efficiency" test "$(json "$TMP/block-cal.json" .efficiency_t1)" = "$eb"
for map in block cyclic; do
  r=$(json "$TMP/$map.json" .memory.ratio_to_pixel_partitioned)
  echo "$map memory / pixel-partitioned = $r"
  check "$map memory ratio $r below 0.5" awk -v r="$r" 'BEGIN { exit !(r < 0.5) }'
done
finish
