#!/usr/bin/env bash
# On paper-image1 at 16 IPs (4x2x2 torus): the cyclic (load-balancing) mapping beats block
# mapping in efficiency_busy, and the data memory requirement is well below the
# pixel-partitioned figure.
source "$(dirname "$0")/common.bash" "$@"
f="$SRC/scenes/paper-image1.nff"
for map in block cyclic; do
  "$BUILD/torusrt-sim" "$f" -o "$TMP/$map.png" --stats "$TMP/$map.json" -q --ips 4x2x2 --map "$map" --t1 1 \
    || fail "run $map"
done
eb=$(json "$TMP/block.json" .efficiency_busy); ec=$(json "$TMP/cyclic.json" .efficiency_busy)
echo "efficiency_busy: block $eb, cyclic $ec"
check "cyclic ($ec) beats block ($eb)" awk -v c="$ec" -v b="$eb" 'BEGIN { exit !(c > b) }'
for map in block cyclic; do
  r=$(json "$TMP/$map.json" .memory.ratio_to_pixel_partitioned)
  echo "$map memory / pixel-partitioned = $r"
  check "$map memory ratio $r below 0.5" awk -v r="$r" 'BEGIN { exit !(r < 0.5) }'
done
finish
