#!/usr/bin/env bash
# Machine files as a user writes them: '#' starts a comment only outside a quoted value (a path
# may hold '#', and its dump reads back to the same machine); a key given twice or in a table
# that is not its own is an error naming the file, the line, the column and the key (exit 2),
# never a silent choice.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
sim="$BUILD/torusrt-sim"

# Paths with '#' (and a space) survive a dump and a read back.
cp "$SRC/timing/literal.timing" "$TMP/lit #1.timing"
"$sim" --dump-config --timing "$TMP/lit #1.timing" > "$TMP/t.toml" 2> "$TMP/err"
check "dump with a '#' timing path exits 0 ($(head -1 "$TMP/err"))" test $? -eq 0
"$sim" --dump-config --config "$TMP/t.toml" > "$TMP/t-again.toml" 2> "$TMP/err"
check "a '#' timing path reads back ($(head -1 "$TMP/err"))" cmp -s "$TMP/t.toml" "$TMP/t-again.toml"
"$sim" "$SRC/scenes/one-pixel.nff" -o "$TMP/w.png" -q --t1 1 --cells 2 --ips 2 --write-map "$TMP/m#2.map" \
    || fail "--write-map run"
"$sim" --dump-config --cells 2 --ips 2 --map-file "$TMP/m#2.map" > "$TMP/m.toml" 2> "$TMP/err"
check "dump with a '#' map-file exits 0 ($(head -1 "$TMP/err"))" test $? -eq 0
"$sim" --dump-config --config "$TMP/m.toml" > "$TMP/m-again.toml" 2> "$TMP/err"
check "a '#' map-file path reads back ($(head -1 "$TMP/err"))" cmp -s "$TMP/m.toml" "$TMP/m-again.toml"

# Comments: whole lines and after a value.
printf '# a machine\nips="2x2" # four nodes\n  # indented\nmap="block"\n' > "$TMP/c.toml"
"$sim" --dump-config --config "$TMP/c.toml" > "$TMP/c-dump.toml" 2> "$TMP/err"
check "comments are skipped ($(head -1 "$TMP/err"))" grep -qx 'ips="2x2x1"' "$TMP/c-dump.toml"
check "comments are skipped: map too" grep -qx 'map="block"' "$TMP/c-dump.toml"

# --dump-config reads the --map-file as a run does: a missing table or one for another grid exits 2.
"$sim" --dump-config --ips 2 --map-file "$TMP/missing.map" > "$TMP/out" 2> "$TMP/err"
rc=$?
check "--dump-config with a missing --map-file exits 2 (got $rc)" test $rc -eq 2
check "--dump-config with a missing --map-file names it ($(head -1 "$TMP/err"))" grep -q "missing.map" "$TMP/err"
"$sim" --dump-config --cells 3 --ips 2 --map-file "$TMP/m#2.map" > "$TMP/out" 2> "$TMP/err"
rc=$?
check "--dump-config with a --map-file for other cells exits 2 (got $rc)" test $rc -eq 2

# A bad value or combination that comes from the file names the file beside the option.
from_file() {  # from_file EXPECTED CONTENT OPTIONS...
    printf '%b' "$2" > "$TMP/m.toml"; local expect=$1; shift 2
    "$sim" --dump-config --config "$TMP/m.toml" "$@" > "$TMP/out" 2> "$TMP/err"
    local rc=$?
    check "'$expect' exits 2 (got $rc)" test $rc -eq 2
    check "message '$expect' ($(head -1 "$TMP/err"))" grep -q -- "$expect" "$TMP/err"
}
from_file "m.toml:1:5: --ips 'zz'" 'ips="zz"\n'
from_file "m.toml:2:9: --quantum: only meaningful with --style lt" 'style="lt"\nquantum="10us"\n' --style at
"$sim" --dump-config --config "$TMP/m.toml" --style at --quantum 10us > "$TMP/out" 2> "$TMP/err"
check "an option from the command line is named without the file ($(head -1 "$TMP/err"))" \
    grep -q "^torusrt-sim: --quantum: only meaningful" "$TMP/err"

# A path with a line break, a backslash and both quotes is written escaped (a TOML basic
# string) and reads back to the same machine.
odd="$TMP/two"$'\n'"lines \\ \"q\" 'l'.timing"
cp "$SRC/timing/literal.timing" "$odd"
"$sim" --dump-config --timing "$odd" > "$TMP/odd.toml" 2> "$TMP/err"
check "--dump-config of a path with a line break exits 0 ($(head -1 "$TMP/err"))" test $? -eq 0
"$sim" --dump-config --config "$TMP/odd.toml" > "$TMP/odd-again.toml" 2> "$TMP/err"
check "the escaped path reads back ($(head -1 "$TMP/err"))" cmp -s "$TMP/odd.toml" "$TMP/odd-again.toml"

# bad_file EXPECTED CONTENT: exit 2, stderr matches EXPECTED, nothing on stdout.
bad_file() {
    printf '%b' "$2" > "$TMP/bad.toml"
    "$sim" --dump-config --config "$TMP/bad.toml" > "$TMP/out" 2> "$TMP/err"
    local rc=$?
    check "'$2' exits 2 (got $rc)" test $rc -eq 2
    check "'$2': message '$1' ($(head -1 "$TMP/err"))" grep -q -- "$1" "$TMP/err"
    check "'$2': no dump" test ! -s "$TMP/out"
}
bad_file "bad.toml:3:5: .*cannot redefine existing string 'ips'" 'ips="2"\nmap="block"\nips="3"\n'
bad_file "bad.toml:2:8: .*cannot redefine existing string 'ips'" 'ips="2"\n ips = "2"\n'
bad_file "bad.toml:1:2: \[machine\]: not a table of a machine file (network, timing, cluster or mapping)" \
    '[machine]\nips="2"\n'
bad_file "bad.toml:2:1: frobnicate: not a machine option" 'ips="2"\nfrobnicate="2"\n'
finish
