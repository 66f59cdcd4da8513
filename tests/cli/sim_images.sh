#!/usr/bin/env bash
# Every model configuration renders the reference image byte for byte: every scene, 1/2/8/16/64
# IPs, each mapping, torus and mesh, each scene at its own size (the paper scenes at 144x144).
source "$(dirname "$0")/common.bash" "$@"
shapes="1 2 2x2x2 4x2x2 4x4x4"
maps="block cyclic block-cyclic:2 block-cyclic:3"
for scene in "$SRC"/scenes/*.nff; do
  name=$(basename "$scene" .nff)
  if ! "$BUILD/torusrt-render" "$scene" -o "$TMP/ref.png" -q; then
    fail "$name: reference render"; continue
  fi
  for ips in $shapes; do
    for map in $maps; do
      for topo in torus mesh; do
        # --t1 skips the one-processor run: only the image matters here.
        if "$BUILD/torusrt-sim" "$scene" -o "$TMP/sim.png" -q --t1 1 --ips "$ips" --map "$map" \
             --topology "$topo" && cmp -s "$TMP/ref.png" "$TMP/sim.png"; then
          pass
        else
          fail "$name --ips $ips --map $map --topology $topo"
        fi
      done
    done
  done
done
finish
