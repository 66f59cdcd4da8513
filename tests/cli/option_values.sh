#!/usr/bin/env bash
# option_values.sh - one parser for every number and list: decimal only (010, 0x10 and hex
# floats refused with "decimal only", on the command line, in machine files and in timing
# files), lists and parameters checked item by item, a bare time in seconds, checks that need
# no scene made before the scene is read, and messages that quote the user's bytes escaped.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
sim="$BUILD/torusrt-sim"
scene=$(source_scene one-pixel) || exit 1
size=(--size 4x4)
time_limit 120

# Integers: one rule for every option (and its machine-file key).
for args in "--queue 010" "--queue 0x10" "--cluster 010" "--cluster 0x10" "--ips 010" "--ips 0x10" \
    "--max-depth 08" "--frames 010 --orbit 90"; do
    # shellcheck disable=SC2086
    bad_option "${args%% *}" "$args" $args
    check "$args: says decimal only ($(head -c 200 "$TMP/bad.stderr"))" grep -q "decimal only" "$TMP/bad.stderr"
done
for key in queue cluster; do
    printf '%s="010"\n' "$key" > "$TMP/m.toml"
    "$sim" --dump-config --config "$TMP/m.toml" > "$TMP/out" 2> "$TMP/err"
    check "machine file $key=\"010\" exits 2 ($?)" [ $? = 2 ] || true
    check "machine file $key=\"010\": file, line, column and decimal only ($(head -1 "$TMP/err"))" \
        grep -q "m.toml:1:[0-9]*: --$key '010': decimal only" "$TMP/err"
done
"$sim" --dump-config --queue 10 | grep -qx 'queue="10"' && pass || fail "--queue 10 is ten"

# Lists and parameters: each item checked, no first number kept.
bad_option "--trace-ips" "--trace-ips 0x10" --ips 2 --vcd "$TMP/bad/t.vcd" --trace-ips 0x10
bad_option "--trace-ips" "--trace-ips 0,,1" --ips 2 --vcd "$TMP/bad/t.vcd" --trace-ips 0,,1
bad_option "--map" "--map block-cyclic:2x99" --map block-cyclic:2x99
bad_option "--map" "--map cost:3x" --map cost:3x
"$sim" --dump-config --map block-cyclic:2 | grep -qx 'map="block-cyclic:2"' && pass || fail "block-cyclic:2 kept"

# Reals: no hex float, inf or nan anywhere.
bad_option "--link-bytes-per-us" "hex float" --link-bytes-per-us 0x1p3
bad_option "--min-weight" "inf weight" --min-weight inf
# A timing file is an input file: exit 1, naming the file and line.
timing_file_bad() {  # timing_file_bad NAME CONTENT EXPECTED
    printf '%b' "$2" > "$TMP/$1.timing"
    "$sim" "$scene" "${size[@]}" -o "$TMP/tf.png" -q --timing "$TMP/$1.timing" 2> "$TMP/err"
    local rc=$?
    check "$1: exit 1 (got $rc)" [ $rc = 1 ]
    check "$1: '$3' ($(head -1 "$TMP/err"))" grep -q "$1.timing:$3" "$TMP/err"
}
timing_file_bad hex 'link 0x1p3\n' "1: 'link' needs a decimal number"
timing_file_bad twice 'link 30\nlink 40\n' "2: 'link' given twice"
timing_file_bad inf 'link inf\n' "1: 'link' needs a decimal number"

# A bare time is seconds for every time option but --link-us; a unit is accepted everywhere.
d=$("$sim" --dump-config --style lt --quantum 0.002 | grep '^quantum=')
check "--quantum 0.002 is 2 ms ($d)" [ "$d" = 'quantum="2000us"' ]
d=$("$sim" --dump-config --link-us 0.5ms | grep '^link-us=')
check "--link-us 0.5ms is 500 us ($d)" [ "$d" = 'link-us="500"' ]
d=$("$sim" --dump-config --link-us 70 | grep '^link-us=')
check "--link-us 70 is 70 us ($d)" [ "$d" = 'link-us="70"' ]
"$sim" "$scene" "${size[@]}" -o "$TMP/tl.png" -q --time-limit 100 2> "$TMP/err"
check "--time-limit 100 is 100 s: the run finishes ($(head -1 "$TMP/err"))" [ -s "$TMP/tl.png" ]
printf 'style="lt"\nquantum="500"\n' > "$TMP/bare.toml"
"$sim" --dump-config --config "$TMP/bare.toml" > "$TMP/out" 2> "$TMP/err"
rc=$?
check "a bare time in a machine file exits 2 (got $rc)" [ $rc = 2 ]
check "a bare time names the file, line, key and rule ($(head -1 "$TMP/err"))" \
    grep -q 'bare.toml:2:1: quantum = "500": a time in a machine file needs its unit' "$TMP/err"

# Messages: the number as given, never 1e+06; the user's bytes escaped and cut short.
bad_option "--link-us" "--link-us 1000001" --link-us 1000001
check "--link-us 1000001: no 1e+06 ($(head -c 200 "$TMP/bad.stderr"))" \
    grep -q "'1000001': must be at most 1000000 us" "$TMP/bad.stderr"
# Times: each option's maximum holds however the number is spelled (a huge integer, 1e307).
for args in "--stats-interval 1e308 --stats-series $TMP/bad/s.csv" "--trace-from 99999999999999999999 --vcd $TMP/bad/t.vcd" \
    "--trace-to 2e7 --vcd $TMP/bad/t.vcd" "--t1 1e8" "--time-limit 1e307"; do
    # shellcheck disable=SC2086
    bad_option "${args%% *}" "$args" $args
    check "$args: names the maximum ($(head -c 200 "$TMP/bad.stderr"))" grep -q "must be at most 10000000 s" "$TMP/bad.stderr"
done
# An option given twice is named with its count, in plain words.
bad_option "--max-depth" "--max-depth twice" --max-depth 2 --max-depth 3
check "--max-depth twice: given 2 times ($(head -c 200 "$TMP/bad.stderr"))" grep -q -- "--max-depth: given 2 times; give it once" "$TMP/bad.stderr"
# A flag given twice is refused the same way (bad_option gives -q once already).
bad_option "--quiet" "-q twice" -q
check "-q twice: given 2 times ($(head -c 200 "$TMP/bad.stderr"))" grep -q -- "--quiet: given 2 times; give it once" "$TMP/bad.stderr"
"$sim" --dump-config --with-timing --with-timing >"$TMP/twice.out" 2>"$TMP/twice.err" </dev/null
check "--with-timing twice: exit 2 ($?), nothing written" [ ! -s "$TMP/twice.out" ]
check "--with-timing twice: named" grep -q -- "--with-timing: given 2 times; give it once" "$TMP/twice.err"
"$BUILD/torusrt-render" "$scene" "${size[@]}" -o "$TMP/bad/r.png" --brute-force --brute-force >/dev/null 2>"$TMP/twice.err" </dev/null
rc=$?
check "render --brute-force twice: exit 2 (got $rc), no image" [ "$rc" = 2 ] && [ ! -e "$TMP/bad/r.png" ]
check "render --brute-force twice: named" grep -q -- "--brute-force: given 2 times; give it once" "$TMP/twice.err"
d=$("$sim" --dump-config --link-us -0 | grep '^link-us=')
check "--link-us -0 is written 0 ($d)" [ "$d" = 'link-us="0"' ]
bad_option "--queue" "control bytes" --queue $'\e]0;owned\a'
check "control bytes are escaped ($(head -c 200 "$TMP/bad.stderr" | od -c | head -2))" \
    sh -c "! grep -q \$(printf '\\033') '$TMP/bad.stderr' && grep -qF '\\x1b]0;owned\\x07' '$TMP/bad.stderr'"
long=$(head -c 100000 /dev/zero | tr '\0' 'x')
bad_option "--queue" "a long value" --queue "$long"
check "a long value is cut to 200 characters ($(wc -c < "$TMP/bad.stderr") bytes)" \
    [ "$(wc -c < "$TMP/bad.stderr")" -lt 400 ]
printf 'ips="2"\nqueue="%s"\n' "$long" > "$TMP/long.toml"
"$sim" --dump-config --config "$TMP/long.toml" > "$TMP/out" 2> "$TMP/err"
check "a long machine-file value: short message naming the file ($(head -c 120 "$TMP/err"))" \
    sh -c "grep -q 'long.toml:2:7: --queue' '$TMP/err' && [ \$(wc -c < '$TMP/err') -lt 400 ]"

# Machine files: a NUL byte or a line without a key is refused, naming the line.
printf 'ips="2"\nmap="block\0junk"\n' > "$TMP/nul.toml"
"$sim" --dump-config --config "$TMP/nul.toml" > "$TMP/out" 2> "$TMP/err"
check "a NUL byte in a machine file exits 2 ($(head -1 "$TMP/err"))" grep -q "nul.toml:2: .*NUL byte" "$TMP/err"
printf 'ips="2"\n=4\n' > "$TMP/nokey.toml"
"$sim" --dump-config --config "$TMP/nokey.toml" > "$TMP/out" 2> "$TMP/err"
check "'=4' in a machine file exits 2 ($(head -1 "$TMP/err"))" grep -q "nokey.toml:2:1: .*expected keys" "$TMP/err"
printf 'link_us="60"\n' > "$TMP/under.toml"
"$sim" --dump-config --config "$TMP/under.toml" > "$TMP/out" 2> "$TMP/err"
check "link_us: did you mean link-us ($(head -1 "$TMP/err"))" grep -q "under.toml:1:1: link_us: .*did you mean link-us" "$TMP/err"
"$sim" "$scene" -o "$TMP/x.png" --lnk-us 60 > "$TMP/out" 2> "$TMP/err"
check "--lnk-us: did you mean --link-us ($(tr '\n' ' ' < "$TMP/err"))" grep -q "did you mean --link-us" "$TMP/err"

# Checks that need no scene come before it is read: a missing scene is not what is reported.
for args in "--map block-cyclic:0" "--orbit 1e308 --frames 3" "--queue 010"; do
    # shellcheck disable=SC2086
    "$sim" "$TMP/no-such-scene.nff" -o "$TMP/f_%d.png" $args > "$TMP/out" 2> "$TMP/err"
    rc=$?
    check "$args: exit 2 before the scene is read (got $rc: $(head -1 "$TMP/err"))" \
        sh -c "[ $rc = 2 ] && ! grep -q no-such-scene '$TMP/err'"
done
bad_option "--orbit" "--orbit 1e308" --frames 3 --orbit 1e308
check "--orbit 1e308: the angle is not finite ($(head -c 200 "$TMP/bad.stderr"))" grep -q "finite" "$TMP/bad.stderr"

# The memory budget exceeded at start-up is said in its own words, not SystemC's.
f=$(source_scene paper-image2) || exit 1
"${run_limited[@]}" "$sim" "$f" -o "$TMP/b.png" -q --size 100x100 --memory-budget 1M 2> "$TMP/err"
rc=$?
check "budget at start-up exits 1 (got $rc)" [ $rc = 1 ]
check "budget at start-up: its own words ($(head -1 "$TMP/err"))" \
    sh -c "grep -q 'memory budget' '$TMP/err' && ! grep -q E546 '$TMP/err'"

# --style lt without --quantum warns.
"$sim" "$scene" "${size[@]}" -o "$TMP/lt.png" --style lt > /dev/null 2> "$TMP/err"
check "--style lt without --quantum warns ($(head -1 "$TMP/err"))" grep -q "warning: --style lt with a quantum of 0" "$TMP/err"
"$sim" "$scene" "${size[@]}" -o "$TMP/lt.png" --style lt --quantum 0 > /dev/null 2> "$TMP/err"
check "--style lt --quantum 0 warns without saying --quantum is missing ($(head -1 "$TMP/err"))" \
    sh -c "grep -q 'warning: --style lt with a quantum of 0' '$TMP/err' && ! grep -q 'without --quantum' '$TMP/err'"
"$sim" "$scene" "${size[@]}" -o "$TMP/lt.png" --style lt --quantum 1ms > /dev/null 2> "$TMP/err"
check "--style lt --quantum 1ms does not warn" sh -c "! grep -q warning '$TMP/err'"
finish
