#!/usr/bin/env bash
# Extreme configurations still give the reference image: more IPs than cells along an axis (IPs
# that own no cells), a 1x1 image, a large image, a non-cubic grid, a 1D ring of 64 and a 2D torus.
source "$(dirname "$0")/common.bash" "$@"
same() { # same DESCRIPTION SCENE "RENDER ARGS" "SIM ARGS"
  local what=$1 scene=$2 rargs=$3 sargs=$4
  # shellcheck disable=SC2086
  if "$BUILD/torusrt-render" "$SRC/scenes/$scene.nff" -o "$TMP/r.png" -q $rargs &&
     "$BUILD/torusrt-sim" "$SRC/scenes/$scene.nff" -o "$TMP/s.png" -q --t1 1 $rargs $sargs &&
     cmp -s "$TMP/r.png" "$TMP/s.png"; then pass; else fail "$what"; fi
}
same "8 IPs on 3 cells along x" scale-1 "--cells 3" "--ips 8x1x1 --map block"
same "64 IPs on 3x3x3 cells" scale-1 "--cells 3" "--ips 4x4x4 --map cyclic"
same "16x2x1 IPs on 3 cells, mesh" scale-1 "--cells 3" "--ips 16x2x1 --topology mesh"
same "1x1 image" paper-image2 "--size 1x1" "--ips 4x2x2"
same "one-pixel scene" one-pixel "" "--ips 2x2x2"
same "large image 640x480" scale-1 "--size 640x480" "--ips 4x2x2"
same "non-cubic grid 5x9x13" paper-image2 "--size 48x48 --cells 5x9x13" "--ips 4x2x2 --map block-cyclic:2"
same "1D ring of 64" paper-image2 "--size 48x48" "--ips 64"
same "2D torus 8x8" paper-image2 "--size 48x48" "--ips 8x8"
same "every object in one cell" one-cell "" "--ips 4x4x4"
same "eye inside the object space" eye-inside "" "--ips 4x2x2 --map block"
same "light inside the object space" light-inside "" "--ips 4x2x2"
same "deep mirrors, max depth 20" facing-mirrors "--max-depth 20" "--ips 2x2x2"
"$BUILD/torusrt-sim" "$SRC/scenes/one-cell.nff" -o "$TMP/o.png" --stats "$TMP/o.json" -q --t1 1 --ips 4x4x4
busiest=$(jq '[.per_ip[].busy_s] | max' "$TMP/o.json"); total=$(jq '[.per_ip[].busy_s] | add' "$TMP/o.json")
check "one-cell: one IP carries most of the load ($busiest of $total s)" \
  awk -v a="$busiest" -v b="$total" 'BEGIN { exit !(a > 0.5 * b) }'
finish
