#!/usr/bin/env bash
# streams_before_parsing.sh - torusrt-sim, torusrt-render and torusrt-genscenes never append a
# message to a file of their command line through their own standard error or output, also
# when the command line is wrong (the parser's messages: a missing -o, an unknown option, an
# option missing its value, -o twice, two scenes): `2>> SCENE` and `>> SCENE` are refused (exit
# 2) before the parser writes, the file unchanged; --dump-config's machine file appended to its
# own --config, --timing or --map-file (or to a timing file the machine file names) is refused
# the same way, and so is any message (a parse error, --help, --version) appended to a file a
# --config machine file names; a file named by an output option stays the stream's to write (--stats r.json
# > r.json, -q: the JSON); and torusrt-genscenes refuses an empty OUTDIR (it would write into
# the root folder).
#
# Usage (CTest runs it so): bash tests/hostile/streams_before_parsing.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim torusrt-render torusrt-genscenes
time_limit 60
f=$(source_scene paper-image1) || exit 1
cd "$TMP" || exit 1
sim=$BUILD/torusrt-sim render=$BUILD/torusrt-render gen=$BUILD/torusrt-genscenes
cp "$f" keep.nff
"$sim" --dump-config --ips 2 >keep.toml </dev/null
printf 'handover_send 100\n' >keep.timing
"$sim" keep.nff -q -o k.png --size 8x8 --ips 2 --write-map keep.map </dev/null
printf 'timing = "t.timing"\n' >keep.cfg  # a machine file naming a timing file
mkdir out

# into STREAM NAME INPUT COMMAND...: COMMAND with standard output (STREAM 1) or error (2)
# appended to INPUT (a copy of keep.EXT first): exit 2, INPUT unchanged, nothing in out/.
into() {
    local stream=$1 name=$2 input=$3
    shift 3
    cp "keep.${input##*.}" "$input"
    if [ "$stream" = 1 ]; then
        "${run_limited[@]}" "$@" >>"$input" 2>err.txt </dev/null
    else
        "${run_limited[@]}" "$@" 2>>"$input" >out.txt </dev/null
    fi
    local rc=$?
    check "$name: exit $rc, expected 2" [ "$rc" -eq 2 ]
    check "$name: $input changed: $(diff "keep.${input##*.}" "$input" 2>&1 | tail -n 2 | head -c 200)" \
        cmp -s "keep.${input##*.}" "$input"
    [ "$stream" = 2 ] || check "$name: the message: $(head -c 300 err.txt)" \
        grep -q "standard output is redirected to .*$input" err.txt
    check "$name: nothing written: $(ls -A out)" [ -z "$(ls -A out)" ]
}
for exe in sim render; do
    x=${!exe}
    into 2 "$exe: no -o, 2>> SCENE" s.nff "$x" s.nff
    into 2 "$exe: unknown option, 2>> SCENE" s.nff "$x" s.nff -o out/o.png --frobnicate
    into 2 "$exe: missing value, 2>> SCENE" s.nff "$x" s.nff -o out/o.png --size
    into 2 "$exe: -o twice, 2>> SCENE" s.nff "$x" s.nff -o out/a.png -o out/b.png
    into 2 "$exe: two scenes, 2>> SCENE" s.nff "$x" s.nff keep.nff -o out/o.png
    into 1 "$exe: unknown option, >> SCENE" s.nff "$x" s.nff -o out/o.png --frobnicate
    into 2 "$exe: --timing=FILE, 2>> it" t.timing "$x" keep.nff -o out/o.png --timing=t.timing --size
done
into 2 "sim: --dump-config --config, bad value, 2>> it" m.toml "$sim" --dump-config --config m.toml --ips zz
into 1 "sim: --dump-config --config >> it" m.toml "$sim" --dump-config --config m.toml
into 1 "sim: --dump-config --timing >> it" t.timing "$sim" --dump-config --timing t.timing
into 1 "sim: --dump-config --map-file >> it" w.map "$sim" --dump-config --ips 2 --map-file w.map
cp keep.cfg m.cfg
into 1 "sim: --dump-config, a timing file the machine file names, >> it" t.timing "$sim" --dump-config --config m.cfg
into 2 "sim: unknown option, 2>> a timing file the machine file names" t.timing "$sim" keep.nff -o out/o.png \
    --config m.cfg --frobnicate
into 1 "sim: --help >> a timing file the machine file names" t.timing "$sim" --config m.cfg --help
into 1 "sim: --version >> a timing file the machine file names" t.timing "$sim" --config=m.cfg --version
into 2 "genscenes: 2>> OUTDIR that is a file" s.nff "$gen" s.nff paper-image1
into 2 "genscenes: --variant, 2>> a word that is a file" s.nff "$gen" --variant paper-image1 zz=1 out s.nff

# An output option naming the file standard output goes to: the stream's to write (-q: the JSON).
"${run_limited[@]}" "$sim" keep.nff -q -o out/o.png --size 8x8 --stats r.json >r.json 2>err.txt </dev/null
check "sim --stats r.json > r.json: exit $?: $(head -c 200 err.txt)" grep -q '"status"' r.json
rm -f out/o.png

# torusrt-genscenes '' NAME: refused, nothing written into the root folder.
[ -e /paper-image1.nff ] && had=1 || had=0
"${run_limited[@]}" "$gen" '' paper-image1 >out.txt 2>err.txt </dev/null
rc=$?
check "genscenes '': exit $rc, expected 2" [ "$rc" -eq 2 ]
check "genscenes '': the message: $(head -c 200 err.txt)" grep -q "OUTDIR: an empty value" err.txt
[ "$had" = 1 ] || { check "genscenes '': no /paper-image1.nff" [ ! -e /paper-image1.nff ]; rm -f /paper-image1.nff; }
# An OUTDIR that is not there, or a file: a usage error (2) naming it, as a missing OUTDIR is.
for dir in nodir keep.nff; do
    "${run_limited[@]}" "$gen" "$dir" one-cell >out.txt 2>err.txt </dev/null
    rc=$?
    check "genscenes $dir: exit $rc, expected 2" [ "$rc" -eq 2 ]
    check "genscenes $dir: the message: $(head -c 200 err.txt)" grep -q "OUTDIR '$dir': \(no such folder\|not a folder\)" err.txt
done
"${run_limited[@]}" "$gen" --variant paper-image1 mirror_reflect=0 '' v >out.txt 2>err.txt </dev/null
rc=$?
check "genscenes --variant '': exit $rc, expected 2" [ "$rc" -eq 2 ]
[ -e /v.nff ] && { check "genscenes --variant '': no /v.nff" false; rm -f /v.nff; }
finish
