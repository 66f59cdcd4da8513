#!/usr/bin/env bash
# The command line as a user meets it: --help lists the exit statuses and shows no TEXT type
# names, --version gives the project version, parser errors carry the program name, one time
# syntax for --link-us, --quantum and the trace window, warnings for idle nodes and a
# min-weight above 1, limits that keep the model from aborting or its time from overflowing.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
f="$SRC/scenes/paper-image2.nff"
small=(--size 16x16 --t1 1)
version=$(sed -n 's/^project(torusrt VERSION \([0-9.]*\).*/\1/p' "$SRC/CMakeLists.txt")

for exe in torusrt-sim torusrt-render; do
    "$BUILD/$exe" --help > "$TMP/help" 2>&1
    check "$exe --help exits 0" test $? -eq 0
    codes=("0 success" "1 bad input" "2 bad command line")
    [ $exe = torusrt-sim ] && codes+=("3 deadlock")
    for code in "${codes[@]}"; do
        check "$exe --help lists exit status '$code'" grep -q "^ *$code" "$TMP/help"
    done
    check "$exe --help shows no TEXT types" bash -c "! grep -q TEXT '$TMP/help'"
    check "$exe --version is '$exe $version'" test "$("$BUILD/$exe" --version)" = "$exe $version"
    "$BUILD/$exe" -o "$TMP/x.png" 2> "$TMP/err"
    check "$exe: missing scene exits 2" test $? -eq 2
    check "$exe: parser error names the program ($(head -1 "$TMP/err"))" grep -q "^$exe: .*scene.* is required" "$TMP/err"
    # The shared options are parsed and checked alike by both (exit 2 naming the option).
    for bad in "--cells 1024" "--cells 0" "--max-depth 1001" "--min-weight -1" "--size 0x10" "--memory-budget lots"; do
        rm -f "$TMP/x.png"
        # shellcheck disable=SC2086 # the option and its value
        "$BUILD/$exe" "$f" -o "$TMP/x.png" -q $bad 2> "$TMP/err"
        check "$exe $bad exits 2" test $? -eq 2
        check "$exe $bad: message names ${bad%% *} ($(head -1 "$TMP/err"))" grep -q -- "^$exe: ${bad%% *}" "$TMP/err"
        check "$exe $bad: no image" test ! -e "$TMP/x.png"
    done
done

# One time syntax: a bare number is microseconds, units ns, us, ms, s.
run_time() { "$BUILD/torusrt-sim" "$f" -o "$TMP/t.png" --stats "$TMP/t.json" --ips 2x2 -q "${small[@]}" "$@" &&
             json "$TMP/t.json" .sim_time_s; }
a=$(run_time --link-us 500) || fail "--link-us 500"
b=$(run_time --link-us 500us) || fail "--link-us 500us"
c=$(run_time --link-us 0.5ms) || fail "--link-us 0.5ms"
check "--link-us 500 = 500us = 0.5ms ($a $b $c)" test -n "$a" -a "$a" = "$b" -a "$b" = "$c"
d=$(run_time --link-us 50) || fail "--link-us 50"
check "--link-us 500 is slower than 50 ($a > $d)" awk -v a="$a" -v d="$d" 'BEGIN { exit !(a > d) }'
# A bare time is seconds, except for --link-us (whose name carries its unit).
q1=$(run_time --style lt --quantum 0.0005) || fail "--quantum 0.0005"
q2=$(run_time --style lt --quantum 500us) || fail "--quantum 500us"
check "--quantum 0.0005 = 500us ($q1 $q2)" test -n "$q1" -a "$q1" = "$q2"

# Warnings (stderr) unless -q. 2x2x2 cells mapped cyclically onto 3x3x3 nodes: each cell's node
# is (x mod 3, y mod 3, z mod 3), so 8 nodes own cells and 19 stay idle.
"$BUILD/torusrt-sim" "$f" -o "$TMP/w.png" --ips 3x3x3 --cells 2 "${small[@]}" >/dev/null 2>"$TMP/err"
check "idle nodes warned: 19 of 27 ($(cat "$TMP/err"))" grep -q "19 of 27 nodes own no cells" "$TMP/err"
"$BUILD/torusrt-sim" "$f" -o "$TMP/w.png" --ips 3x3x3 --cells 2 "${small[@]}" -q >/dev/null 2>"$TMP/err"
check "-q silences the idle warning" test ! -s "$TMP/err"
"$BUILD/torusrt-sim" "$f" -o "$TMP/w.png" --ips 2x2 --cells 8 "${small[@]}" >/dev/null 2>"$TMP/err"
check "no idle warning when every node owns cells" bash -c "! grep -q 'own no cells' '$TMP/err'"
for exe in torusrt-sim torusrt-render; do
    "$BUILD/$exe" "$f" -o "$TMP/m.png" --size 16x16 --min-weight 2 >/dev/null 2>"$TMP/err"
    check "$exe --min-weight 2 warns that every secondary ray is dropped" grep -q "every secondary ray is dropped" "$TMP/err"
done

# Limits: exit 2 with a message, never an abort.
lim() {
    local expect=$1 code=$2; shift 2
    rm -f "$TMP/l.png"
    local t1=(--t1 1)
    case "$*" in *--t1*) t1=() ;; esac
    "$BUILD/torusrt-sim" "$f" -o "$TMP/l.png" -q --size 16x16 "${t1[@]}" "$@" >/dev/null 2>"$TMP/err"
    local rc=$?
    check "$* exits $code (got $rc)" test $rc -eq "$code"
    check "$*: message mentions '$expect' ($(head -c 200 "$TMP/err"))" grep -q -- "$expect" "$TMP/err"
    check "$*: no image left" test ! -e "$TMP/l.png"
}
lim "--ips" 2 --ips 65536
lim "--ips" 2 --ips 32768
lim "at most 4096 processors" 2 --ips 16x16x16 --cluster 2
lim "--link-us" 2 --link-us 1e11
lim "--link-us" 2 --link-us 1e300
lim "--link-bytes-per-us" 2 --link-bytes-per-us 1e-300
lim "--t1" 2 --t1 1e308
lim "--t1" 2 --t1 inf
lim "--trace-from" 2 --trace-from 1s
printf 'link 1e300\n' > "$TMP/huge.timing"
lim "huge.timing" 1 --timing "$TMP/huge.timing"
"$BUILD/torusrt-render" "$f" -o "$TMP/r.png" -q --size 16x16 --timing "$TMP/huge.timing" 2>"$TMP/err"
check "render: a timing value that would make T(1) infinite exits 1" test $? -eq 1
# Simulated time past --time-limit (the 4-node image takes several simulated seconds): exit 1.
lim "passed the limit of 1 s" 1 --ips 2x2 --time-limit 1s --stats "$TMP/l.json"
check "--time-limit: no stats left" test ! -e "$TMP/l.json"
finish
