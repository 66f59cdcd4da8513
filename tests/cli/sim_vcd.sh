#!/usr/bin/env bash
# A VCD trace from a small run converts with GTKWave's vcd2fst and holds the traced signals;
# --trace-ips limits it to the named nodes.
source "$(dirname "$0")/common.bash" "$@"
f="$SRC/scenes/paper-image2.nff"
"$BUILD/torusrt-sim" "$f" -o "$TMP/a.png" --vcd "$TMP/a.vcd" -q --ips 2x2x1 --size 24x24 --t1 1 || fail "traced run"
check "vcd written" test -s "$TMP/a.vcd"
check "vcd2fst converts it" vcd2fst "$TMP/a.vcd" "$TMP/a.fst"
check "fst written" test -s "$TMP/a.fst"
for sig in "ip_0 \$end" "busy" "queue_depth" "link_0_to_1_xp"; do
  check "vcd has $sig" grep -q "$sig" "$TMP/a.vcd"
done
check "value changes recorded" grep -q '^#[1-9]' "$TMP/a.vcd"
# A link's busy line is driven by a process the link makes only when traced: it must go up and
# come down again.
busy_id=$(awk '/scope module link_0_to_1_xp /{ in_link = 1 } in_link && /busy/ { print $4; exit }' "$TMP/a.vcd")
check "link_0_to_1_xp.busy declared" test -n "$busy_id"
check "link_0_to_1_xp.busy goes up" grep -qx "1$busy_id" "$TMP/a.vcd"
check "link_0_to_1_xp.busy comes down" bash -c "grep -x '0$busy_id' '$TMP/a.vcd' | sed -n 2p | grep -q ."
"$BUILD/torusrt-sim" "$f" -o "$TMP/b.png" --vcd "$TMP/b.vcd" -q --ips 2x2x1 --size 24x24 --t1 1 --trace-ips 1 || fail "limited run"
check "--trace-ips 1 keeps ip_1" grep -q 'ip_1' "$TMP/b.vcd"
check "--trace-ips 1 drops ip_0" bash -c "! grep -q 'scope module ip_0 ' '$TMP/b.vcd'"
check "no temporary files left" bash -c "! ls '$TMP' | grep -q tmp"
finish
