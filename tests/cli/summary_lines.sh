#!/usr/bin/env bash
# The summary explains itself: the system line gives the timing style, the buffers and the flow
# scheme; figures have 4 significant digits; the packets line says the missed rays are primary
# rays that missed the scene; "wrote" lists every output (--write-map and --load-map too), and
# torusrt-render says what it wrote; an animation's image time says it spans all frames.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
f="$SRC/scenes/paper-image1.nff"
sim=("$BUILD/torusrt-sim" "$f" --t1 1 --size 16x16)
(cd "$TMP" && "${sim[@]}" -o a.png --stats a.json --ips 2x2 --queue 3 --write-map m.map --load-map l.png) \
    > "$TMP/sum" 2> /dev/null || fail "run"
line() { grep -A1 "^  $1 " "$TMP/sum" | tr -s ' ' | tr '\n' ' '; }
check "system: timing style, buffers, flow scheme ($(line system))" \
    grep -qF "approximately timed (AT), 3 packets per buffer and class, flow control classes (deadlock-free)" "$TMP/sum"
check "wrote: every output in order" grep -qx "  wrote        a.png, a.json, m.map, l.png" "$TMP/sum"
for out in a.png a.json m.map l.png; do check "$out exists" test -s "$TMP/$out"; done
t=$(jq .sim_time_s "$TMP/a.json")
want=$(python3 -c 'import math, sys; v = float(sys.argv[1]); print("%.*f" % (max(3 - math.floor(math.log10(v)), 0), v))' "$t")
check "image time at 4 significant digits ($want for $t)" grep -q "^  image time   $want s simulated" "$TMP/sum"
check "busy per IP at 4 significant digits" grep -qE '^  busy per IP  min [0-9]+\.[0-9]+  mean' "$TMP/sum"
check "the missed rays are primary rays that missed the scene" \
    grep -qx "               primary rays that missed the scene $(jq .packets.primary_missed "$TMP/a.json")" "$TMP/sum"
check "no 'at timing' left" test "$(grep -c ' at timing' "$TMP/sum")" -eq 0
"${sim[@]}" -o "$TMP/lt.png" --ips 2x2 --style lt --quantum 1ms --flow none > "$TMP/lt" 2> /dev/null || fail "lt run"
check "LT, unbounded, none named" \
    grep -qF "loosely timed (LT, quantum 1000 us), unbounded buffers, flow control none (finite buffers may deadlock)" "$TMP/lt"
(cd "$TMP" && "$BUILD/torusrt-render" "$f" --size 16x16 -o r.png --stats r.json --cost-image c.png) > "$TMP/rsum" ||
    fail "render"
check "torusrt-render says what it wrote" grep -qx "  wrote        r.png, r.json, c.png" "$TMP/rsum"
"$BUILD/torusrt-render" "$f" --size 16x16 -o "$TMP/q.png" -q > "$TMP/qsum"
check "quiet: nothing on stdout" test ! -s "$TMP/qsum"
(cd "$TMP" && "$BUILD/torusrt-sim" "$f" --size 16x16 -o f_%d.png --ips 2 --orbit 20 --frames 3 --frames-csv f.csv) > "$TMP/an" 2> /dev/null ||
    fail "animation"
check "animation: the time spans the frames" grep -q "^  time         [0-9.]* s simulated over 3 frames" "$TMP/an"
check "animation: no 'image time' line for the whole animation" test "$(grep -c '^  image time' "$TMP/an")" -eq 0
check "animation: the total at 4 significant digits" \
    grep -qE "^  animation    3 frames, remap static: total [0-9]+\.[0-9]+ s = images" "$TMP/an"
total=$(grep -oE "total [0-9.]+ s" "$TMP/an" | grep -oE "[0-9.]+")
check "animation: the total has 4 significant digits ($total)" test "$(printf %s "$total" | tr -d . | sed 's/^0*//' | wc -c)" -eq 4
frame0=$(awk '$1 == "0" && $NF == "first" {print $2}' "$TMP/an")
check "animation: frame 0's image time at 4 significant digits ($frame0)" \
    test "$(printf %s "$frame0" | tr -d . | sed 's/^0*//' | wc -c)" -eq 4
check "animation: wrote the frames and the CSV" grep -qx "  wrote        3 frames f_%d.png, f.csv" "$TMP/an"
finish
