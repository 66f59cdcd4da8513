#!/usr/bin/env bash
# With both hand-over keys and the link at 0, splitting the work over n IPs adds nothing:
# the IPs' busy times sum to T(1) exactly (compared in whole picoseconds, SystemC's
# resolution), for several machine sizes and mappings. The literal profile and
# timing/literal.timing give the same run, and every report names its profile.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
f=$(source_scene paper-image1) || exit 1
printf 'handover_send 0\nhandover_receive 0\nlink 0\n' > "$TMP/zero.timing"
for run in "2 block" "4 cyclic" "2x2x2 block-cyclic:2" "4x2x2 cyclic" "3x3 block-cyclic:3" "4x2x2 block"; do
  set -- $run
  "$BUILD/torusrt-sim" "$f" -o "$TMP/z.png" --stats "$TMP/z.json" -q --size 48x48 --ips "$1" --map "$2" \
    --timing "$TMP/zero.timing" || { fail "$run: run"; continue; }
  sum=$(jq '[.per_ip[].busy_s * 1e12 | round] | add' "$TMP/z.json")
  t1=$(jq '.t1_s * 1e12 | round' "$TMP/z.json")
  fw=$(jq '.packets.forwarded' "$TMP/z.json")
  check "$run: busy sum $sum ps equals T(1) $t1 ps ($fw hand-overs)" test "$sum" = "$t1"
  check "$run: there were hand-overs to cost nothing" test "$fw" -gt 0
  check "$run: profile named" test "$(json "$TMP/z.json" .config.timing_profile)" != ""
done
# The same machine with hand-overs charged takes longer than the busy-sum bound.
"$BUILD/torusrt-sim" "$f" -o "$TMP/l.png" --stats "$TMP/l.json" -q --size 48x48 --ips 4x2x2 --timing-profile literal \
  || fail "literal profile run"
"$BUILD/torusrt-sim" "$f" -o "$TMP/lf.png" --stats "$TMP/lf.json" -q --size 48x48 --ips 4x2x2 \
  --timing "$SRC/timing/literal.timing" --timing-profile literal || fail "literal file run"
check "literal profile = timing/literal.timing" test "$(json "$TMP/l.json" .sim_time_s)" = "$(json "$TMP/lf.json" .sim_time_s)"
check "profile reported" test "$(json "$TMP/l.json" .config.timing_profile)" = literal
check "profile + file reported" test "$(json "$TMP/lf.json" .config.timing_profile)" = "literal + $SRC/timing/literal.timing"
# timing/calibrated.timing holds the calibrated profile; the default is fitted.
"$BUILD/torusrt-sim" "$f" -o "$TMP/d.png" --stats "$TMP/d.json" -q --size 8x8 || fail "default run"
check "default profile is fitted" test "$(json "$TMP/d.json" .config.timing_profile)" = fitted
"$BUILD/torusrt-sim" "$f" -o "$TMP/c.png" --stats "$TMP/c.json" -q --size 48x48 --ips 4x2x2 \
  --timing-profile calibrated || fail "calibrated run"
"$BUILD/torusrt-sim" "$f" -o "$TMP/cf.png" --stats "$TMP/cf.json" -q --size 48x48 --ips 4x2x2 \
  --timing-profile literal --timing "$SRC/timing/calibrated.timing" || fail "calibrated file run"
check "calibrated profile = timing/calibrated.timing" test "$(json "$TMP/c.json" .sim_time_s)" = "$(json "$TMP/cf.json" .sim_time_s)"
check "calibrated is faster than literal" jq -e --slurpfile l "$TMP/l.json" '.sim_time_s < $l[0].sim_time_s' "$TMP/c.json"
sum=$(jq '[.per_ip[].busy_s] | add' "$TMP/l.json"); t1=$(json "$TMP/l.json" .t1_s)
check "literal hand-overs cost busy time ($sum > $t1)" awk -v a="$sum" -v b="$t1" 'BEGIN { exit !(a > b) }'
"$BUILD/torusrt-sim" "$f" -o "$TMP/bad.png" -q --size 8x8 --timing-profile nonesuch 2>"$TMP/err"
check "unknown profile: exit 2" test $? -eq 2
check "unknown profile: named" grep -q nonesuch "$TMP/err"
check "unknown profile: no output" test ! -e "$TMP/bad.png"
finish
