#!/usr/bin/env bash
# A VCD trace from a small run converts with GTKWave's vcd2fst and holds the traced signals;
# --trace-ips limits it to the named nodes.
source "$(dirname "$0")/common.bash" "$@"
f="$SRC/scenes/paper-image2.nff"
"$BUILD/torusrt-sim" "$f" -o "$TMP/a.png" --stats "$TMP/a.json" --vcd "$TMP/a.vcd" -q --ips 2x2x1 --size 24x24 --t1 1 || fail "traced run"
check "vcd written" test -s "$TMP/a.vcd"
check "vcd2fst converts it" vcd2fst "$TMP/a.vcd" "$TMP/a.fst"
check "fst written" test -s "$TMP/a.fst"
for sig in "ip_0 \$end" "busy" "queue_depth" "link_0_to_1_xp"; do
  check "vcd has $sig" grep -q "$sig" "$TMP/a.vcd"
done
check "value changes recorded" grep -q '^#[1-9]' "$TMP/a.vcd"
# A link's use (percent of each window of 100 packet times it was busy) is driven by a process the
# link makes only when traced: it rises, comes back to 0, stays in [0, 100], and over the run it
# integrates to the link's busy time in the JSON (each window rounded to a percent).
use_id=$(awk '/scope module link_0_to_1_xp /{ in_link = 1 } in_link && / use / { print $4; exit }' "$TMP/a.vcd")
check "link_0_to_1_xp.use declared" test -n "$use_id"
awk -v id="$use_id" '/^#/ { t = substr($1, 2) + 0 } $2 == id && /^b/ { v = 0; b = substr($1, 2)
    for (i = 1; i <= length(b); i++) v = 2 * v + substr(b, i, 1); printf "%.0f %d\n", t, v }' "$TMP/a.vcd" > "$TMP/use.txt"
check "link_0_to_1_xp.use rises" awk '$2 > 0 { ok = 1 } END { exit !ok }' "$TMP/use.txt"
check "link_0_to_1_xp.use comes back to 0" test "$(tail -1 "$TMP/use.txt" | cut -d' ' -f2)" = 0
check "link_0_to_1_xp.use stays in [0, 100]" awk '$2 < 0 || $2 > 100 { bad = 1 } END { exit bad }' "$TMP/use.txt"
busy=$(jq '[.links.per_link[] | select(.from == 0 and .to == 1 and .dir == "xp") | .busy_s] | add' "$TMP/a.json")
check "link_0_to_1_xp.use integrates to its busy time ($busy s)" awk -v want="$busy" '
    NR > 1 { s += pv * ($1 - pt) } { pt = $1; pv = $2 } END { got = s / 100 / 1e12; d = got - want; if (d < 0) d = -d
        if (d > 0.02 * want) { print "got " got > "/dev/stderr"; exit 1 } }' "$TMP/use.txt"
"$BUILD/torusrt-sim" "$f" -o "$TMP/b.png" --vcd "$TMP/b.vcd" -q --ips 2x2x1 --size 24x24 --t1 1 --trace-ips 1 || fail "limited run"
check "--trace-ips 1 keeps ip_1" grep -q 'ip_1' "$TMP/b.vcd"
check "--trace-ips 1 drops ip_0" bash -c "! grep -q 'scope module ip_0 ' '$TMP/b.vcd'"
sleep 1  # another second on the wall clock: the trace must not carry it
"$BUILD/torusrt-sim" "$f" -o "$TMP/c.png" --vcd "$TMP/c.vcd" -q --ips 2x2x1 --size 24x24 --t1 1 --trace-ips 1 || fail "again"
check "the same run gives a byte-identical trace (no wall-clock date)" cmp -s "$TMP/b.vcd" "$TMP/c.vcd"
check "no temporary files left" bash -c "! ls '$TMP' | grep -q tmp"
finish
