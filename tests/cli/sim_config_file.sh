#!/usr/bin/env bash
# --config and --dump-config: a machine dumped with --dump-config and read back with --config
# gives the same run as the same options on the command line (image bytes, simulated time and
# the JSON config); the command line overrides the file; a bad file exits 2 naming the file or
# the key and leaves no output; the scene and the outputs never come from a file.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
f="$SRC/scenes/paper-image1.nff"
sim="$BUILD/torusrt-sim"
small=(--size 32x32)

# round_trip NAME OPTIONS...: --dump-config OPTIONS, then a run from that file against a run
# with OPTIONS on the command line.
round_trip() {
    local name=$1; shift
    "$sim" --dump-config "$@" > "$TMP/$name.toml" 2> "$TMP/$name.err"
    check "$name: --dump-config exits 0 ($(head -c 200 "$TMP/$name.err"))" test $? -eq 0
    check "$name: --dump-config writes nothing to stderr" test ! -s "$TMP/$name.err"
    "$sim" "$f" -o "$TMP/$name-file.png" --stats "$TMP/$name-file.json" -q "${small[@]}" --config "$TMP/$name.toml" ||
        fail "$name: run from the file"
    "$sim" "$f" -o "$TMP/$name-cli.png" --stats "$TMP/$name-cli.json" -q "${small[@]}" "$@" ||
        fail "$name: run from the command line"
    check "$name: same image bytes" cmp -s "$TMP/$name-file.png" "$TMP/$name-cli.png"
    local a b
    a=$(json "$TMP/$name-file.json" .sim_time_s) b=$(json "$TMP/$name-cli.json" .sim_time_s)
    check "$name: same sim_time_s ($a $b)" test -n "$a" -a "$a" = "$b"
    check "$name: same JSON config" cmp -s <(jq -S .config "$TMP/$name-file.json") <(jq -S .config "$TMP/$name-cli.json")
}
round_trip flat --ips 4x2x2 --map block
round_trip cluster --ips 2x2 --cluster 2 --data shared
# The file really set the machine: the default run is a different one.
"$sim" "$f" -o "$TMP/default.png" --stats "$TMP/default.json" -q "${small[@]}" || fail "default run"
check "the cluster file's machine differs from the default" \
    test "$(json "$TMP/cluster-file.json" .sim_time_s)" != "$(json "$TMP/default.json" .sim_time_s)"

# The dump holds the options given and the defaults of the others, and no files to write.
d="$TMP/flat.toml"
check "dump has ips = 4x2x2" grep -qx 'ips="4x2x2"' "$d"
check "dump has map = block" grep -qx 'map="block"' "$d"
check "dump has the default cells = 24" grep -qx 'cells=24' "$d"
check "dump has the default style = at" grep -qx 'style="at"' "$d"
"$sim" --dump-config --ips 4x2x2 -o "$TMP/no.png" --stats "$TMP/no.json" > "$TMP/outs.toml"
check "dump with -o and --stats exits 0" test $? -eq 0
check "dump names no output or scene" bash -c "! grep -Eq '^(output|stats|vcd|scene|write-map|load-map|config|dump-config)=' '$TMP/outs.toml'"
check "dump writes no output file" test ! -e "$TMP/no.png" -a ! -e "$TMP/no.json"
# A dump of a file plus options parses back to the same dump.
"$sim" --dump-config --config "$d" --cluster 2 > "$TMP/again.toml" || fail "dump of a file"
"$sim" --dump-config --config "$TMP/again.toml" > "$TMP/again2.toml" || fail "dump parses back"
check "dump of a dump is the same" cmp -s "$TMP/again.toml" "$TMP/again2.toml"
check "dump of a file keeps its ips and adds --cluster" grep -qx 'ips="4x2x2"' "$TMP/again.toml"
check "dump of a file has cluster = 2" grep -qx 'cluster=2' "$TMP/again.toml"
# --map-file replaces --map: no conflicting map key in the dump, and the dump reads back.
"$sim" --dump-config --map-file "$TMP/some.map" > "$TMP/mapfile.toml" || fail "dump with --map-file"
check "dump with --map-file has no map key" bash -c "! grep -q '^map=' '$TMP/mapfile.toml'"
"$sim" --dump-config --config "$TMP/mapfile.toml" > /dev/null
check "dump with --map-file reads back" test $? -eq 0

# The command line overrides the file.
"$sim" "$f" -o "$TMP/over.png" --stats "$TMP/over.json" -q "${small[@]}" --config "$d" --ips 2x2 || fail "override run"
"$sim" "$f" -o "$TMP/want.png" --stats "$TMP/want.json" -q "${small[@]}" --ips 2x2 --map block || fail "override reference"
check "--ips on the command line overrides the file" \
    cmp -s <(jq -S .config "$TMP/over.json") <(jq -S .config "$TMP/want.json")
check "override: same image" cmp -s "$TMP/over.png" "$TMP/want.png"

# Bad files: exit 2, a message naming the file or the key, no output left.
bad_file() {
    local expect=$1 content=$2
    printf '%s\n' "$content" > "$TMP/bad.toml"
    rm -rf "$TMP/out"; mkdir -p "$TMP/out"
    "$sim" "$f" -o "$TMP/out/x.png" --stats "$TMP/out/x.json" -q "${small[@]}" --config "$TMP/bad.toml" 2> "$TMP/err"
    local rc=$?
    check "'$content' exits 2 (got $rc)" test $rc -eq 2
    check "'$content': message has '$expect' ($(head -1 "$TMP/err"))" grep -q -- "$expect" "$TMP/err"
    check "'$content': no output left" test -z "$(ls -A "$TMP/out")"
}
bad_file "bad.toml: .*frobnicate" 'frobnicate=3'
bad_file "bad.toml: .*output" 'output="elsewhere.png"'
bad_file "bad.toml: .*stats" 'stats="elsewhere.json"'
bad_file "--queue" 'queue="lots"'
bad_file "--ips" 'ips="abc"'
bad_file "--map" 'map="spiral"'
"$sim" "$f" -o "$TMP/m.png" --config "$TMP/missing.toml" 2> "$TMP/err"
check "a missing --config file exits 2" test $? -eq 2
check "a missing --config file is named" grep -q "missing.toml" "$TMP/err"
"$sim" --dump-config --ips 0 > /dev/null 2> "$TMP/err"
check "--dump-config checks the values (--ips 0 exits 2)" test $? -eq 2

# Without --dump-config the scene and -o are still required.
"$sim" --config "$d" -o "$TMP/r.png" 2> "$TMP/err"
check "no scene exits 2" test $? -eq 2
check "no scene: message" grep -q "^torusrt-sim: scene is required" "$TMP/err"
"$sim" "$f" --config "$d" 2> "$TMP/err"
check "no -o exits 2" test $? -eq 2
check "no -o: message" grep -q "^torusrt-sim: --output is required" "$TMP/err"
finish
