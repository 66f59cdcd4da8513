#!/usr/bin/env bash
# Finite queues on stiff scenes end, within a bounded time, with either the correct image or a
# clear deadlock report (exit 3, full queues named, no output files). Never a hang.
source "$(dirname "$0")/common.bash" "$@"
for scene in one-cell facing-mirrors paper-image2; do
  f="$SRC/scenes/$scene.nff"
  [ -f "$f" ] || { fail "missing $f"; continue; }
  "$BUILD/torusrt-render" "$f" -o "$TMP/ref.png" -q --size 32x32 || fail "$scene reference"
  for q in 1 2 4 64; do
    rm -f "$TMP/sim.png"
    timeout 120 "$BUILD/torusrt-sim" "$f" -o "$TMP/sim.png" -q --t1 1 --size 32x32 --ips 2x2x2 --queue "$q" 2> "$TMP/err"
    rc=$?
    if [ $rc -eq 0 ]; then
      check "$scene --queue $q image" cmp -s "$TMP/ref.png" "$TMP/sim.png"
    elif [ $rc -eq 3 ]; then
      check "$scene --queue $q deadlock report names full queues" grep -q "full: " "$TMP/err"
      check "$scene --queue $q no image after deadlock" test ! -e "$TMP/sim.png"
    else
      fail "$scene --queue $q: exit $rc (timeout or crash)"
    fi
  done
done
finish
