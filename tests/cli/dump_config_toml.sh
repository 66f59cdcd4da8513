#!/usr/bin/env bash
# dump_config_toml.sh - --dump-config writes TOML that Python's tomllib reads for any path
# (backslashes, both quotes, control bytes, '#'), which reads back to the same machine;
# --with-timing makes a machine file that needs no timing file; and
# `experiments/report machine` writes a report's machine exactly as --dump-config does, grouped
# in tables (flat for a report without config.option_tables, which reads the same); a run
# with --timing-values and its dump are one machine, and a dump without it another.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
sim="$BUILD/torusrt-sim"
scene=$(source_scene one-pixel) || exit 1

# toml_reads FILE TABLE KEY VALUE: tomllib reads FILE, and KEY of [TABLE] holds VALUE.
toml_reads() {
    python3 -c 'import sys, tomllib
with open(sys.argv[1], "rb") as f: d = tomllib.load(f)
sys.exit(0 if d[sys.argv[2]][sys.argv[3]] == sys.argv[4] else 1)' "$@" 2> "$TMP/py.err"
}
names=("back\\slash" "double\"quote" "single'quote" "both\"and'" "hash #1" $'tab\there' $'bell\a' $'line\nbreak' "naïve")
k=0
for name in "${names[@]}"; do
    k=$((k + 1))
    dir="$TMP/d$k"
    mkdir -p "$dir"
    path="$dir/$name.timing"
    cp "$SRC/timing/literal.timing" "$path"
    "$sim" --dump-config --timing "$path" > "$dir/m.toml" 2> "$TMP/err"
    check "dump with path $k exits 0 ($(head -1 "$TMP/err"))" [ $? = 0 ]
    check "tomllib reads the dump of path $k ($(tail -1 "$TMP/py.err" 2>/dev/null))" toml_reads "$dir/m.toml" timing timing "$path"
    "$sim" --dump-config --config "$dir/m.toml" > "$dir/again.toml" 2> "$TMP/err"
    check "path $k reads back to the same machine ($(head -1 "$TMP/err"))" cmp -s "$dir/m.toml" "$dir/again.toml"
done

# Every time is written with its unit.
"$sim" --dump-config --style lt --quantum 3ms > "$TMP/q.toml"
check "quantum with its unit ($(grep '^quantum' "$TMP/q.toml"))" grep -qx 'quantum="3000us"' "$TMP/q.toml"

# --with-timing: every timing value in the file, no timing file needed.
cp "$SRC/timing/literal.timing" "$TMP/own.timing"
"$sim" --dump-config --timing "$TMP/own.timing" --ips 2 --with-timing > "$TMP/self.toml" 2> "$TMP/err"
check "--with-timing exits 0 ($(head -1 "$TMP/err"))" [ $? = 0 ]
check "--with-timing writes timing-values" grep -q '^timing-values="test_miss=' "$TMP/self.toml"
check "--with-timing names no timing file" grep -qx 'timing=""' "$TMP/self.toml"
"$sim" "$scene" -o "$TMP/a.png" --stats "$TMP/a.json" -q --t1 1 --timing "$TMP/own.timing" --ips 2 || fail "run with the file"
rm "$TMP/own.timing"
"$sim" "$scene" -o "$TMP/b.png" --stats "$TMP/b.json" -q --t1 1 --config "$TMP/self.toml" 2> "$TMP/err" ||
    fail "run of the self-contained machine file: $(head -1 "$TMP/err")"
check "the self-contained file gives the same image time ($(json_get "$TMP/a.json" sim_time_s) $(json_get "$TMP/b.json" sim_time_s))" \
    [ -n "$(json_get "$TMP/a.json" sim_time_s)" ] && [ "$(json_get "$TMP/a.json" sim_time_s)" = "$(json_get "$TMP/b.json" sim_time_s)" ]
"$sim" "$scene" -o "$TMP/c.png" -q --with-timing 2> /dev/null
rc=$?
check "--with-timing without --dump-config exits 2 (got $rc)" [ $rc = 2 ]

# The report's machine file is --dump-config's, key for key and in its order.
machine=(--ips 2x1 --map block --queue 8 --style lt --quantum 2ms --cluster 2 --timing-profile literal)
"$sim" "$scene" -o "$TMP/r.png" --stats "$TMP/r.json" -q --t1 1 "${machine[@]}" || fail "report run"
"$sim" --dump-config "${machine[@]}" > "$TMP/dump.toml"
python3 "$SRC/experiments/report" machine "$TMP/r.json" > "$TMP/report.toml" 2> "$TMP/err"
check "report machine exits 0 ($(head -1 "$TMP/err"))" [ $? = 0 ]
check "report machine = --dump-config ($(diff "$TMP/dump.toml" "$TMP/report.toml" | head -3 | tr '\n' ' '))" \
    cmp -s "$TMP/dump.toml" "$TMP/report.toml"
check "the report's machine file is grouped ($(grep -c '^\[' "$TMP/report.toml") tables)" \
    [ "$(grep -c '^\[' "$TMP/report.toml")" = 4 ]
# A report without config.option_tables (written before tables) gives a flat file: the same machine.
jq 'del(.config.option_tables)' "$TMP/r.json" >"$TMP/flat.json"
python3 "$SRC/experiments/report" machine "$TMP/flat.json" >"$TMP/flat.toml" 2>"$TMP/err"
check "report machine of a report without tables exits 0 ($(head -1 "$TMP/err"))" [ $? = 0 ]
check "... and writes no table" [ "$(grep -c '^\[' "$TMP/flat.toml")" = 0 ]
"$sim" --dump-config --config "$TMP/flat.toml" >"$TMP/flat.dump" 2>"$TMP/err"
check "the flat file is the same machine ($(head -1 "$TMP/err"))" cmp -s "$TMP/dump.toml" "$TMP/flat.dump"

# --timing-values is part of the machine: in the dump without --with-timing, and in the report,
# so that a machine without it compares as another machine.
"$sim" "$scene" -o "$TMP/v.png" --stats "$TMP/v.json" -q --t1 1 --ips 2 --timing-values host_inject=9 ||
    fail "run with --timing-values"
"$sim" --dump-config --ips 2 --timing-values host_inject=9 >"$TMP/v.toml"
check "the dump holds --timing-values" grep -q '^timing-values=".*,host_inject=9,' "$TMP/v.toml"
python3 "$SRC/experiments/report" machine "$TMP/v.json" --compare "$TMP/v.toml" >/dev/null 2>&1
check "report machine --compare: the run and its dump are the same machine (exit $?)" [ $? = 0 ]
"$sim" --dump-config --ips 2 >"$TMP/plain.toml"
python3 "$SRC/experiments/report" machine "$TMP/v.json" --compare "$TMP/plain.toml" >/dev/null 2>"$TMP/cmp.err"
rc=$?
check "report machine --compare: without --timing-values another machine (exit $rc)" [ $rc = 1 ]
check "report machine --compare names timing-values" grep -q "timing-values" "$TMP/cmp.err"
finish
