#!/usr/bin/env bash
# The VCD has no SystemC noise (fractional link times used to warn on every change), uses one
# timescale for flat and cluster runs, comes with a GTKWave save file whose every signal is in
# the VCD, and a --trace-from/--trace-to window keeps only the changes inside it.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
f="$SRC/scenes/paper-image2.nff"
sim() { "$BUILD/torusrt-sim" "$f" --size 16x16 --t1 1 "$@"; }

# 28 bytes at 3 bytes/us is 9.33.. us per hop: not a whole microsecond (nor nanosecond).
sim -o "$TMP/a.png" --vcd "$TMP/a.vcd" --ips 2x2 --link-bytes-per-us 3 >"$TMP/a.out" 2>"$TMP/a.err" || fail "traced run"
check "no W713 on stdout or stderr" bash -c "! grep -q W713 '$TMP/a.out' '$TMP/a.err'"
check "nothing from SystemC on stdout" bash -c "! grep -Eq '^(Info|Warning|Error): \\(' '$TMP/a.out'"
check "save file written beside the VCD" test -s "$TMP/a.gtkw"
sim -o "$TMP/q.png" --vcd "$TMP/q.vcd" --ips 2x2 --link-bytes-per-us 3 -q >"$TMP/q.out" 2>"$TMP/q.err" || fail "quiet run"
check "-q: nothing on stdout" test ! -s "$TMP/q.out"
check "-q: nothing on stderr" test ! -s "$TMP/q.err"

sim -o "$TMP/c.png" --vcd "$TMP/c.vcd" --ips 2 --cluster 2 -q || fail "cluster traced run"
timescale() { awk '/\$timescale/ { getline; print $1 $2; exit }' "$1"; }
check "flat timescale is 1 ps ($(timescale "$TMP/a.vcd"))" test "$(timescale "$TMP/a.vcd")" = 1ps
check "cluster timescale is 1 ps ($(timescale "$TMP/c.vcd"))" test "$(timescale "$TMP/c.vcd")" = 1ps

# Full names of the VCD's variables (scopes joined with '.', vectors with their range) and the
# signal lines of the save file (every line that is not a flag, label or [setting]).
vcd_names() {
    awk '/\$scope/ { s[++d] = $3 } /\$upscope/ { d-- }
         /\$var/ { n = ""; for (i = 1; i <= d; i++) n = n s[i] "."; v = $5; if ($6 ~ /^\[/) v = v $6; print n v }
         /\$enddefinitions/ { exit }' "$1" | sort -u
}
gtkw_names() { grep -v -e '^@' -e '^-' -e '^\[' -e '^\*' "$1" | sed 's/^+{[^}]*} //' | sort -u; }
for t in a c; do
    nodes=4; [ $t = c ] && nodes=2
    vcd_names "$TMP/$t.vcd" > "$TMP/$t.vcd.names"
    gtkw_names "$TMP/$t.gtkw" > "$TMP/$t.gtkw.names"
    check "$t: save file lists signals" test -s "$TMP/$t.gtkw.names"
    missing=$(comm -13 "$TMP/$t.vcd.names" "$TMP/$t.gtkw.names" | head -3)
    check "$t: every save-file signal is in the VCD (missing: $missing)" test -z "$missing"
    check "$t: every VCD signal is in the save file" test -z "$(comm -23 "$TMP/$t.vcd.names" "$TMP/$t.gtkw.names")"
    check "$t: save file names its VCD beside it" grep -qxF "[dumpfile] \"$t.vcd\"" "$TMP/$t.gtkw"
    check "$t: queue depths shown decimal (flag @24 before each)" \
        awk '/queue_depth/ { if (prev != "@24") bad = 1; n++ } { prev = $0 } END { exit bad || n == 0 }' "$TMP/$t.gtkw"
    check "$t: the processors' busy group, then one group per node" \
        test "$(grep -A1 '^@800200$' "$TMP/$t.gtkw" | grep '^-[^-]' | tr '\n' ' ')" = \
        "-processors busy $(for ((n = 0; n < nodes; n++)); do printf -- '-node %d ' "$n"; done)"
done
check "links named by their ends" grep -q 'link_0_to_1_xp' "$TMP/a.vcd.names"
check "cluster bus in the save file" grep -q 'cluster_1.bus.owner' "$TMP/c.gtkw.names"

# A window from 1 s to 2 s of a 3.6 s image: fewer changes, smaller file, times inside it.
sim -o "$TMP/w.png" --vcd "$TMP/w.vcd" --ips 2x2 --link-bytes-per-us 3 --trace-from 1s --trace-to 2000ms -q || fail "windowed run"
changes() { grep -c '^#' "$1"; }
check "window: fewer time steps ($(changes "$TMP/w.vcd") < $(changes "$TMP/a.vcd"))" \
    test "$(changes "$TMP/w.vcd")" -lt "$(changes "$TMP/a.vcd")"
check "window: smaller file" test "$(stat -c %s "$TMP/w.vcd")" -lt "$(stat -c %s "$TMP/a.vcd")"
check "window: every time within [1 s, 2 s] in ps" \
    awk '/^#/ { t = substr($0, 2) + 0; n++; if (t < 1e12 || t > 2e12) bad = 1 } END { exit bad || n == 0 }' "$TMP/w.vcd"
check "window: same signals as the full trace" test "$(vcd_names "$TMP/w.vcd")" = "$(cat "$TMP/a.vcd.names")"
check "window: vcd2fst converts it" vcd2fst "$TMP/w.vcd" "$TMP/w.fst"
check "window: save file starts at 1 s" grep -qx '\[timestart\] 1000000000000' "$TMP/w.gtkw"
check "no temporary files left" bash -c "! ls '$TMP' | grep -q tmp"
finish
