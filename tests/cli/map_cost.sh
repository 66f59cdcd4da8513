#!/usr/bin/env bash
# --map cost (pilot run + Scotch) renders the reference PNG byte for byte and conserves
# packets at several machine shapes, flat and clustered, torus and mesh; the mapping is
# reproducible; the report keeps the pilot and mapper costs apart from the image time.
source "$(dirname "$0")/common.bash" "$@"
jq_true() { jq -e "$@" >/dev/null; }
need_exe torusrt-sim torusrt-render
S="$BUILD/torusrt-sim"
for scene in paper-image1 paper-image2; do
  f=$(source_scene $scene) || exit 1
  render_ok "$scene-ref" "$f" "$TMP/ref.png" --size 48x48 || continue
  for run in "4x4x4 torus 1" "8 torus 1" "3x2 mesh 1" "2x2x2 torus 4" "2x2 mesh 3"; do
    set -- $run
    what="$scene $1 $2 cluster $3"
    "$S" "$f" -o "$TMP/c.png" --stats "$TMP/c.json" -q --size 48x48 --ips "$1" --topology "$2" --cluster "$3" \
      --map cost --write-map "$TMP/c.map" || { fail "$what: run"; continue; }
    check "$what: reference image" cmp -s "$TMP/ref.png" "$TMP/c.png"
    check "$what: conserved" test "$(json "$TMP/c.json" .packets.conserved)" = true
    check "$what: mapping kind" test "$(json "$TMP/c.json" .mapping.kind)" = cost
    check "$what: pilot modelled time is T(1) without hand-overs" \
      jq_true '(.mapping.pilot_modelled_s - .t1_s | fabs) <= 1e-9 * .t1_s' "$TMP/c.json"
    check "$what: mapper wall time reported" jq_true '.mapping.mapper_wall_s >= 0 and .mapping.pilot_wall_s >= 0' "$TMP/c.json"
    nodes=$(json "$TMP/c.json" .config.nodes)
    check "$what: table header" grep -q "^torusrt-map 1 24 24 24 $nodes\$" "$TMP/c.map"
  done
done
f=$(source_scene paper-image1) || exit 1
render_ok ref1 "$f" "$TMP/ref.png" --size 48x48 || exit 1
for i in 1 2; do
  "$S" "$f" -o "$TMP/d$i.png" --stats "$TMP/d$i.json" -q --size 48x48 --ips 4x2x2 --map cost --write-map "$TMP/d$i.map" \
    || fail "repeat $i"
done
check "same mapping twice" cmp -s "$TMP/d1.map" "$TMP/d2.map"
check "same time twice" test "$(json "$TMP/d1.json" .sim_time_s)" = "$(json "$TMP/d2.json" .sim_time_s)"
# Folded: Scotch maps onto a machine twice as large per axis, folded back onto the nodes.
"$S" "$f" -o "$TMP/k.png" --stats "$TMP/k.json" -q --size 48x48 --ips 2x2x2 --map cost:2 --write-map "$TMP/k.map" \
  || fail "cost:2"
check "cost:2: reference image" cmp -s "$TMP/ref.png" "$TMP/k.png"
check "cost:2: fold reported" test "$(json "$TMP/k.json" .mapping.fold)" = 2
check "cost:2: every node owns cells" jq_true '.mapping.cells_per_node.min > 0' "$TMP/k.json"
check "cost:2: a different table" bash -c "! cmp -s '$TMP/k.map' '$TMP/d1.map'"
"$S" "$f" -o "$TMP/k0.png" -q --size 48x48 --ips 2 --map cost:0 2>/dev/null
check "cost:0: exit 2" test $? -eq 2
# A smaller pilot still maps every cell and renders the full image.
"$S" "$f" -o "$TMP/p.png" --stats "$TMP/p.json" -q --size 48x48 --ips 4x2x2 --map cost --pilot-size 16x16 \
  || fail "small pilot"
check "small pilot: reference image" cmp -s "$TMP/ref.png" "$TMP/p.png"
check "small pilot: size reported" test "$(jq -c .mapping.pilot_size "$TMP/p.json")" = "[16,16]"
check "small pilot: pilot cheaper than T(1)" jq_true '.mapping.pilot_modelled_s < .t1_s' "$TMP/p.json"
"$S" "$f" -o "$TMP/x.png" -q --size 48x48 --ips 2 --map cyclic --pilot-size 8x8 2>"$TMP/x.err"
check "--pilot-size without --map cost: exit 2" test $? -eq 2
check "--pilot-size without --map cost: no output" test ! -e "$TMP/x.png"
"$S" "$f" -o "$TMP/y.png" -q --size 48x48 --ips 2 --map cost --pilot-size 0x8 2>"$TMP/y.err"
check "--pilot-size 0x8: exit 2" test $? -eq 2
finish
