#!/usr/bin/env bash
# --config and --dump-config: a machine dumped with --dump-config and read back with --config
# gives the same run as the same options on the command line (image bytes and the whole JSON
# report but its wall-clock figures), and so does the machine file rebuilt from the report's
# config.options; the report's machine and the dump agree key by key; the command line
# overrides the file; a bad file exits 2 naming the file or the key and leaves no output; the
# run's options (scene, size, outputs, tracing, limits) never come from a file.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
f="$SRC/scenes/paper-image1.nff"
sim="$BUILD/torusrt-sim"
report=(python3 "$SRC/experiments/report")
run=(--size 32x32 --memory-budget 2G)  # run options: given to every run, never in the file
# The report without the wall-clock figures (they differ from run to run).
timeless() {
    jq -S 'del(.wall_s, .elaboration_wall_s, .sim_wall_s, .events_per_s, .packet_hops_per_s, .mapping.pilot_wall_s, .mapping.mapper_wall_s)' "$1"
}
same_run() {  # same_run WHAT A B: same image, same report but for the wall-clock figures
    check "$1: same image bytes" cmp -s "$TMP/$2.png" "$TMP/$3.png"
    check "$1: same sim_time_s" test "$(json "$TMP/$2.json" .sim_time_s)" = "$(json "$TMP/$3.json" .sim_time_s)"
    check "$1: same JSON report" cmp -s <(timeless "$TMP/$2.json") <(timeless "$TMP/$3.json")
}
sim_run() {  # sim_run NAME OPTIONS...: a run writing NAME.png and NAME.json
    local name=$1; shift
    "$sim" "$f" -o "$TMP/$name.png" --stats "$TMP/$name.json" -q "${run[@]}" "$@" || fail "$name: run ($*)"
}

# round_trip NAME MACHINE-OPTIONS...
round_trip() {
    local name=$1; shift
    "$sim" --dump-config "${run[@]}" "$@" > "$TMP/$name.toml" 2> "$TMP/$name.err"
    check "$name: --dump-config exits 0 ($(head -c 200 "$TMP/$name.err"))" test $? -eq 0
    check "$name: --dump-config writes nothing to stderr" test ! -s "$TMP/$name.err"
    sim_run "$name-cli" "$@"
    sim_run "$name-file" --config "$TMP/$name.toml"
    same_run "$name: --config of the dump" "$name-cli" "$name-file"
    # The report's machine is the dump's, key by key, and a machine file rebuilt from it runs the same.
    "${report[@]}" machine "$TMP/$name-cli.json" --compare "$TMP/$name.toml" > "$TMP/$name.cmp" 2>&1
    check "$name: report config.options = dump, key by key ($(tail -3 "$TMP/$name.cmp"))" test $? -eq 0
    "${report[@]}" machine "$TMP/$name-cli.json" > "$TMP/$name-report.toml" || fail "$name: machine file from the report"
    sim_run "$name-report" --config "$TMP/$name-report.toml"
    same_run "$name: --config of the report's machine" "$name-cli" "$name-report"
    "$sim" --dump-config --config "$TMP/$name.toml" > "$TMP/$name-again.toml" || fail "$name: dump of the dump"
    check "$name: the dump of a dump is the same" cmp -s "$TMP/$name.toml" "$TMP/$name-again.toml"
}
round_trip flat --ips 4x2x2 --map block-cyclic:2 --topology mesh --queue 500 --cells 12x16x20 --link-us 0.08ms \
    --packet-bytes 32 --max-depth 5 --min-weight 1/256 --timing-profile literal
round_trip cluster --ips 2x2 --cluster 3 --data shared --arbiter fixed-priority --dispatch shortest-queue \
    --style lt --quantum 200us --timing "$SRC/timing/literal.timing" --link-bytes-per-us 2
round_trip cost --ips 2x1x2 --map cost:2 --pilot-size 16x16
"$sim" "$f" -o "$TMP/w.png" -q "${run[@]}" --ips 3 --map block --write-map "$TMP/w.map" || fail "--write-map run"
round_trip mapfile --ips 3 --map-file "$TMP/w.map"
check "with --map-file the dump has no map key" bash -c "! grep -q '^map=' '$TMP/mapfile.toml'"
# The file really set the machine: the default run is a different one.
sim_run default
check "the cluster file's machine differs from the default" \
    test "$(json "$TMP/cluster-file.json" .sim_time_s)" != "$(json "$TMP/default.json" .sim_time_s)"

# The dump holds every machine option (the defaults of those not given) and nothing of the run.
d="$TMP/flat.toml"
check "dump has ips" grep -qx 'ips="4x2x2"' "$d"
check "dump has map" grep -qx 'map="block-cyclic:2"' "$d"
check "dump has link-us in microseconds" grep -qx 'link-us="80"' "$d"
check "dump has the default cluster" grep -qx 'cluster="1"' "$d"
check "dump has the default style" grep -qx 'style="at"' "$d"
"$sim" --dump-config --ips 4x2x2 -o "$TMP/no.png" --stats "$TMP/no.json" --t1 3 --time-limit 9s -q > "$TMP/outs.toml"
check "dump with run options exits 0" test $? -eq 0
check "dump names nothing of the run" bash -c "! grep -Eq '^(output|stats|vcd|scene|size|memory-budget|t1|time-limit|trace-[a-z]+|quiet|write-map|load-map|config|dump-config)=' '$TMP/outs.toml'"
check "dump writes no output file" test ! -e "$TMP/no.png" -a ! -e "$TMP/no.json"
"$sim" --dump-config --config "$d" --cluster 2 > "$TMP/again.toml" || fail "dump of a file"
check "dump of a file keeps its ips and adds --cluster" grep -qx 'ips="4x2x2"' "$TMP/again.toml"
check "dump of a file has cluster = 2" grep -qx 'cluster="2"' "$TMP/again.toml"

# The command line overrides the file.
sim_run over --config "$d" --ips 2x2
"$sim" --dump-config --config "$d" --ips 2x2 > "$TMP/over.toml"
check "--ips on the command line overrides the file" grep -qx 'ips="2x2x1"' "$TMP/over.toml"
sed 's/^ips=.*/ips="2x2x1"/' "$d" > "$TMP/want.toml"
sim_run want --config "$TMP/want.toml"
same_run "override" over want

# Bad files: exit 2, a message naming the file or the key, no output left.
bad_file() {
    local expect=$1 content=$2
    printf '%s\n' "$content" > "$TMP/bad.toml"
    rm -rf "$TMP/out"; mkdir -p "$TMP/out"
    "$sim" "$f" -o "$TMP/out/x.png" --stats "$TMP/out/x.json" -q "${run[@]}" --config "$TMP/bad.toml" 2> "$TMP/err"
    local rc=$?
    check "'$content' exits 2 (got $rc)" test $rc -eq 2
    check "'$content': message has '$expect' ($(head -1 "$TMP/err"))" grep -q -- "$expect" "$TMP/err"
    check "'$content': no output left" test -z "$(ls -A "$TMP/out")"
}
bad_file "bad.toml:1:1: .*frobnicate" 'frobnicate=3'
for key in output stats size memory-budget t1 time-limit trace-ips vcd quiet; do
    bad_file "bad.toml:1:1: .*$key" "$key=\"1\""
done
bad_file "--queue" 'queue="lots"'
bad_file "--ips" 'ips="abc"'
bad_file "--map" 'map="spiral"'
bad_file "--cluster" 'cluster="999"'
"$sim" "$f" -o "$TMP/m.png" --config "$TMP/missing.toml" 2> "$TMP/err"
check "a missing --config file exits 2" test $? -eq 2
check "a missing --config file is named" grep -q "missing.toml" "$TMP/err"
"$sim" --dump-config --ips 0 > /dev/null 2> "$TMP/err"
check "--dump-config checks the values (--ips 0 exits 2)" test $? -eq 2
# --map and --map-file: one on the command line replaces the other from the file; both in one place is an error.
"$sim" --dump-config --config "$TMP/mapfile.toml" --ips 3 --map block > "$TMP/mf-map.toml" 2> "$TMP/err"
check "--map replaces a file's map-file ($(head -1 "$TMP/err"))" grep -qx 'map="block"' "$TMP/mf-map.toml"
check "--map replaces a file's map-file: no file left" grep -qx 'map-file=""' "$TMP/mf-map.toml"
"$sim" --dump-config --config "$TMP/flat.toml" --cells 24 --ips 3 --map-file "$TMP/w.map" > "$TMP/flat-mf.toml"
check "--map-file replaces a file's map" bash -c "! grep -q '^map=' '$TMP/flat-mf.toml'"
check "--map-file replaces a file's map: the file is used" grep -qx "map-file=\"$TMP/w.map\"" "$TMP/flat-mf.toml"
sim_run flat-mapfile --config "$TMP/flat.toml" --cells 24 --ips 3 --map-file "$TMP/w.map"
check "a run with --map-file over a file's map uses the table" test "$(json "$TMP/flat-mapfile.json" .mapping.kind)" = file
"$sim" --dump-config --map block --map-file "$TMP/w.map" > /dev/null 2> "$TMP/err"
check "--map and --map-file on the command line exit 2" test $? -eq 2
check "--map and --map-file on the command line: message" grep -q -- "--map-file: give either" "$TMP/err"
printf 'map="block"\nmap-file="%s"\n' "$TMP/w.map" > "$TMP/both.toml"
"$sim" --dump-config --config "$TMP/both.toml" > /dev/null 2> "$TMP/err"
check "map and map-file in one file exit 2" test $? -eq 2

# Without --dump-config the scene and -o are still required.
"$sim" --config "$d" -o "$TMP/r.png" 2> "$TMP/err"
check "no scene exits 2" test $? -eq 2
check "no scene: message" grep -q "^torusrt-sim: scene is required" "$TMP/err"
"$sim" "$f" --config "$d" 2> "$TMP/err"
check "no -o exits 2" test $? -eq 2
check "no -o: message" grep -q "^torusrt-sim: --output is required" "$TMP/err"
finish
