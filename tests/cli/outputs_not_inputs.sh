#!/usr/bin/env bash
# An output naming one of the run's input files (the --config machine file, the --timing file,
# the --map-file table) is a command-line error (exit 2): the input is left as it was.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
f="$SRC/scenes/paper-image1.nff"
sim=("$BUILD/torusrt-sim" "$f" -q --t1 1 --size 8x8)
"$BUILD/torusrt-sim" --dump-config --ips 2 > "$TMP/m.toml" || fail "dump"
cp "$SRC/timing/literal.timing" "$TMP/t.timing"
"${sim[@]}" -o "$TMP/w.png" --ips 2 --write-map "$TMP/w.map" || fail "--write-map run"
cp "$TMP/m.toml" "$TMP/m.keep"; cp "$TMP/t.timing" "$TMP/t.keep"; cp "$TMP/w.map" "$TMP/w.keep"
refused() {  # refused WHAT INPUT KEPT OPTIONS...
    local what=$1 input=$2 kept=$3; shift 3
    "$@" > /dev/null 2> "$TMP/err"
    local rc=$?
    check "$what: exit 2 (got $rc: $(head -1 "$TMP/err"))" test $rc -eq 2
    check "$what: the input is unchanged" cmp -s "$input" "$kept"
    cp "$kept" "$input"
}
refused "--stats onto the --config file" "$TMP/m.toml" "$TMP/m.keep" "${sim[@]}" -o "$TMP/a.png" --config "$TMP/m.toml" --stats "$TMP/m.toml"
refused "--stats onto the --timing file" "$TMP/t.timing" "$TMP/t.keep" "${sim[@]}" -o "$TMP/a.png" --timing "$TMP/t.timing" --stats "$TMP/t.timing"
refused "-o onto the --map-file table" "$TMP/w.map" "$TMP/w.keep" "${sim[@]}" -o "$TMP/w.map" --ips 2 --map-file "$TMP/w.map"
refused "torusrt-render --stats onto the --timing file" "$TMP/t.timing" "$TMP/t.keep" \
    "$BUILD/torusrt-render" "$f" -q --size 8x8 -o "$TMP/r.png" --timing "$TMP/t.timing" --stats "$TMP/t.timing"
finish
