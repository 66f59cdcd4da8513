#!/usr/bin/env bash
# The GTKWave save file beside a VCD opens in the real GTKWave (under Xvfb) ready to read: the
# window covers the whole run, or the --trace-from/--trace-to window; it opens on a group of every
# processor's busy row alone, then a group per node; a link's row is its use in percent drawn as an
# analog step, its peak in its name; every row has a distinct name saying what it is; the dump is
# found relative to the save file, so the pair can be moved.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
for tool in gtkwave xvfb-run; do
    command -v "$tool" > /dev/null || { fail "$tool is not installed (scripts/setup.sh installs it)"; finish; exit; }
done
sim=("$BUILD/torusrt-sim" "$SRC/scenes/paper-image1.nff" -q --t1 1 --size 16x16)
# probe NAME FILE.gtkw: GTKWave's view of FILE.gtkw, opened from another folder, in $TMP/NAME.probe.
probe() {
    (cd / && timeout 120 xvfb-run -a gtkwave -S "$SRC/tests/cli/gtkwave_probe.tcl" "$2") > "$TMP/$1.out" 2>&1
    check "$1: gtkwave ran and quit (status $?)" grep -q '^PROBE max' "$TMP/$1.out"
    grep '^PROBE ' "$TMP/$1.out" | sed 's/^PROBE //' > "$TMP/$1.probe"
}
value() { awk -v k="$2" '$1 == k { print $2 }' "$TMP/$1.probe"; }
# rows NAME: the signal rows' names (the group rows are named "processors busy" and "node N").
rows() { sed -n 's/^row //p' "$TMP/$1.probe" | grep -v '^node [0-9]*$' | grep -vx 'processors busy'; }

mkdir -p "$TMP/run/out" "$TMP/moved"
(cd "$TMP/run" && "${sim[@]}" -o out/a.png --stats out/a.json --ips 4x2x2 --vcd out/t.vcd) || fail "traced run"
check "the save file names the dump relative to its folder" grep -qx '\[dumpfile\] "t.vcd"' "$TMP/run/out/t.gtkw"
mv "$TMP/run/out/t.vcd" "$TMP/run/out/t.gtkw" "$TMP/moved/"
probe whole "$TMP/moved/t.gtkw"
end_ps=$(jq '.sim_time_s * 1e12 | floor' "$TMP/run/out/a.json")
start=$(value whole start); end=$(value whole end); max=$(value whole max)
check "the window starts at 0 ($start)" test "$start" = 0
check "the window reaches the end of the run ($end >= $max, $end_ps)" test "$end" -ge "$max" -a "$end" -ge "$end_ps"
check "the run fills most of the window ($end <= 1.5 x $max)" test "$end" -le $((max * 3 / 2))
rows whole > "$TMP/whole.rows"
check "GTKWave shows every signal of the save file ($(wc -l < "$TMP/whole.rows") rows)" \
    test "$(wc -l < "$TMP/whole.rows")" -eq "$(grep -c '^+{' "$TMP/moved/t.gtkw")"
check "every row's name is distinct: $(sort "$TMP/whole.rows" | uniq -d | head -3 | tr '\n' ';')" \
    test -z "$(sort "$TMP/whole.rows" | uniq -d)"
for name in "ip 3 busy" "ip 3 queue" "link 3->2 -x queue" "link 3->11 +z queue"; do
    check "a row is named '$name'" grep -qxF "$name" "$TMP/whole.rows"
done
for name in "link 3->0 +x use" "link 3->7 +y use" "link 3->7 -y use"; do
    check "a row is named '$name % (peak N)'" grep -qE "^${name//+/\\+} % \(peak [0-9]{1,3}\)\$" "$TMP/whole.rows"
done
check "no link row is a busy flag" test -z "$(grep '^link .* busy$' "$TMP/whole.rows")"
sed -n 's/^row //p' "$TMP/whole.probe" | head -18 > "$TMP/first.rows"
check "the window opens on the group of the processors' busy rows, ip 0 to ip 15 in order, alone" \
    test "$(cat "$TMP/first.rows")" = "$(echo 'processors busy'; for i in $(seq 0 15); do echo "ip $i busy"; done; echo 'processors busy')"
check "then a group per node" test "$(grep -c '^row node ' "$TMP/whole.probe")" -eq 32
check "no processor's busy row in a node's group" test "$(grep -c '^ip .* busy$' "$TMP/whole.rows")" -eq 16
check "every link's use is an analog step (flags 0x88024)" \
    test "$(grep -B1 '^+{link .* use' "$TMP/moved/t.gtkw" | grep -c '^@88024$')" -eq 96

"${sim[@]}" -o "$TMP/w.png" --ips 4x2x2 --vcd "$TMP/w.vcd" --trace-from 1ms --trace-to 3ms || fail "windowed run"
probe window "$TMP/w.gtkw"
start=$(value window start); end=$(value window end)
check "the window starts at --trace-from ($start)" test "$start" = 1000000000
check "the window covers --trace-to, with the span filling most of it ($end)" \
    test "$end" -ge 3000000000 -a "$end" -le 4000000000

"${sim[@]}" -o "$TMP/c.png" --ips 2 --cluster 3 --vcd "$TMP/c.vcd" || fail "cluster run"
probe cluster "$TMP/c.gtkw"
rows cluster > "$TMP/cluster.rows"
check "every row of a cluster trace is distinct" test -z "$(sort "$TMP/cluster.rows" | uniq -d)"
for name in "ip 4 busy" "bus 1 owner" "bus 1 request 2" "bus 1 request cu" "dispatcher 1 busy" "dispatcher 1 queue"; do
    check "a cluster row is named '$name'" grep -qxF "$name" "$TMP/cluster.rows"
done
finish
