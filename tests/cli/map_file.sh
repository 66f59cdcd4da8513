#!/usr/bin/env bash
# --write-map then --map-file gives the same image and the same simulated time, flat and
# clustered; the written table equals the re-written one. Bad tables (missing file, wrong
# cell count, node out of range, garbage, wrong header) are rejected naming the file and
# line, exit 2, no output.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
f=$(source_scene paper-image1) || exit 1
S="$BUILD/torusrt-sim"
common=(-q --size 48x48 --cells 8)
render_ok ref "$f" "$TMP/ref.png" --size 48x48 --cells 8 || exit 1
for run in "4x2x2 block-cyclic:3 1" "3x3 block 1" "2x2 cyclic 4"; do
  set -- $run
  "$S" "$f" -o "$TMP/a.png" --stats "$TMP/a.json" "${common[@]}" --ips "$1" --map "$2" --cluster "$3" \
    --write-map "$TMP/a.map" || { fail "$run: write"; continue; }
  "$S" "$f" -o "$TMP/b.png" --stats "$TMP/b.json" "${common[@]}" --ips "$1" --map-file "$TMP/a.map" --cluster "$3" \
    --write-map "$TMP/b.map" || { fail "$run: read"; continue; }
  check "$run: header" grep -q "^torusrt-map 1 8 8 8 " "$TMP/a.map"
  check "$run: same table" cmp -s "$TMP/a.map" "$TMP/b.map"
  check "$run: same image" cmp -s "$TMP/a.png" "$TMP/b.png"
  check "$run: reference image" cmp -s "$TMP/ref.png" "$TMP/b.png"
  check "$run: same sim_time_s" test "$(json "$TMP/a.json" .sim_time_s)" = "$(json "$TMP/b.json" .sim_time_s)"
  check "$run: mapping kind file" test "$(json "$TMP/b.json" .mapping.kind)" = file
done
# A hand-made table: every cell on node 1 of 2 (node 0 idle) still renders the reference.
{ echo "torusrt-map 1 8 8 8 2   # header"; for i in $(seq 512); do echo 1; done; } > "$TMP/one.map"
"$S" "$f" -o "$TMP/one.png" --stats "$TMP/one.json" "${common[@]}" --ips 2 --map-file "$TMP/one.map" \
  || fail "hand-made table"
check "hand-made table: reference image" cmp -s "$TMP/ref.png" "$TMP/one.png"
check "hand-made table: node 0 idle" test "$(json "$TMP/one.json" '.per_ip[0].packets_in')" = 0
bad() { # NAME EXPECTED_TEXT then the table on stdin
  local name=$1 want=$2
  cat > "$TMP/$name.map"
  "$S" "$f" -o "$TMP/$name.png" --stats "$TMP/$name.json" "${common[@]}" --ips 2 --map-file "$TMP/$name.map" \
    --write-map "$TMP/$name.out" 2>"$TMP/$name.err"
  local rc=$?
  check "$name: exit 2 (got $rc)" test $rc -eq 2
  check "$name: message names '$want': $(cat "$TMP/$name.err")" grep -q -- "$want" "$TMP/$name.err"
  check "$name: no output" test ! -e "$TMP/$name.png" -a ! -e "$TMP/$name.json" -a ! -e "$TMP/$name.out"
}
printf 'torusrt-map 1 8 8 8 2\n0 1 0\n' | bad short "short.map:3: only 3 node ids for 512 cells"
{ echo "torusrt-map 1 8 8 8 2"; for i in $(seq 513); do echo 0; done; } | bad long "long.map:514: more node ids"
{ echo "torusrt-map 1 8 8 8 2"; echo "0 0 2"; } | bad range "range.map:2: cell 2: expected a node id 0..1, found '2'"
{ echo "torusrt-map 1 8 8 8 2"; echo "# ok"; echo "0 zero"; } | bad garbage "garbage.map:3: cell 1: expected a node id 0..1, found 'zero'"
{ echo "torusrt-map 1 8 8 8 2"; echo "-1"; } | bad negative "negative.map:2: cell 0"
echo "torusrt-map 1 24 24 24 2" | bad cells "cells.map:1: header NX = 24, but the run has 8"
echo "torusrt-map 1 8 8 8 4" | bad nodes "nodes.map:1: header NODES = 4, but the run has 2"
echo "0 1 0 1" | bad header "header.map:1: expected the header"
echo "torusrt-map 01 8 8 8 2" | bad version "version.map:1: unsupported map format version (expected 1 or 2, decimal"
echo "torusrt-map 1 08 8 8 2" | bad zeros "zeros.map:1: header: expected a positive decimal number (no sign, no leading zero) for 'NX'"
: | bad empty "empty.map:1: empty map file"
rm -f "$TMP/missing.map"

"$S" "$f" -o "$TMP/m.png" "${common[@]}" --ips 2 --map-file "$TMP/nowhere.map" 2>"$TMP/m.err"
check "missing file: exit 2" test $? -eq 2
check "missing file: named" grep -q "nowhere.map: cannot open" "$TMP/m.err"
check "missing file: no output" test ! -e "$TMP/m.png"
"$S" "$f" -o "$TMP/x.png" "${common[@]}" --ips 2 --map block --map-file "$TMP/a.map" 2>"$TMP/x.err"
check "--map with --map-file: exit 2" test $? -eq 2
finish
