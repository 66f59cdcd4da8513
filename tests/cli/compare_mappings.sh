#!/usr/bin/env bash
# experiments/compare-mappings draws busy time per node of several mappings in one PNG and
# prints each mapping's figures, which agree with a run of that mapping; bad input exits non-zero.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
cm=("$SRC/experiments/compare-mappings" "$SRC/scenes/paper-image1.nff" --build "$BUILD")
"${cm[@]}" --map block,cyclic --out "$TMP/m.png" -- --ips 2x2 --size 16x16 > "$TMP/out.txt" 2> "$TMP/err.txt"
check "it runs: $(head -c 300 "$TMP/err.txt")" test $? -eq 0
check "the picture is a PNG" sh -c "file '$TMP/m.png' | grep -q 'PNG image data'"
check "one line per mapping" test "$(grep -cE '^(block|cyclic) ' "$TMP/out.txt")" -eq 2
check "it says what it wrote" grep -qF "wrote $TMP/m.png" "$TMP/out.txt"
"$BUILD/torusrt-sim" "$SRC/scenes/paper-image1.nff" -q -o "$TMP/b.png" --stats "$TMP/b.json" --ips 2x2 --size 16x16 \
    --map block || fail "block run"
want=$(jq -r '[.per_ip[] | .busy_s] | max | "\(.)"' "$TMP/b.json")
got=$(awk '$1 == "block" { print $4 }' "$TMP/out.txt")
check "block's busiest node ($got s) is the run's ($want s)" \
    python3 -c "import sys; a, b = float(sys.argv[1]), float(sys.argv[2]); sys.exit(abs(a - b) > 1e-3 * b)" "$got" "$want"
"${cm[@]}" --map block,nosuch --out "$TMP/n.png" -- --ips 2x2 --size 16x16 > /dev/null 2> "$TMP/bad.txt"
check "a bad mapping exits 1" test $? -eq 1
check "a bad mapping is named" grep -q 'nosuch' "$TMP/bad.txt"
check "a bad mapping leaves no picture" test ! -e "$TMP/n.png"
"${cm[@]}" --out "$TMP/no/such/m.png" -- --ips 2x2 --size 16x16 > /dev/null 2>&1
check "a missing output folder exits 2" test $? -eq 2
check "no temporaries left in the output folder" test "$(ls "$TMP" | grep -c tmp)" -eq 0
finish
