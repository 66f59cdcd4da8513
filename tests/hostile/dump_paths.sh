#!/usr/bin/env bash
# dump_paths.sh - --dump-config names the files a machine reads (timing, map-file) so that a
# run from the dump, which reads a machine file's relative paths from the machine file's own
# folder, reads the same files: a dump written into another folder that holds a file of the same
# name runs as the command line did; a dump of a dump is the same file; the JSON's
# config.options names the same file, so `report machine --compare` sees two different timing
# files and no difference for the same one.
#
# Usage (CTest runs it so): bash tests/hostile/dump_paths.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
time_limit 60
f=$(source_scene paper-image1) || exit 1
sim=("$BUILD/torusrt-sim" -q --t1 1 --size 16x16)
report=(python3 "$SRC/experiments/report")
cd "$TMP" || exit 1
mkdir sub
cp "$SRC/timing/literal.timing" lit.timing
cp "$SRC/timing/calibrated.timing" sub/lit.timing  # the same name, other values, beside the dump

# The timing file: a dump into sub/ still names ./lit.timing.
"$BUILD/torusrt-sim" --dump-config --ips 2 --timing lit.timing >sub/d.toml 2>err.txt
check "dump with a relative --timing: exit $?: $(head -c 200 err.txt)" [ -s sub/d.toml ]
"${run_limited[@]}" "${sim[@]}" "$f" -o a.png --ips 2 --timing lit.timing --stats a.json 2>err.txt
check "run with --timing lit.timing: exit $?: $(head -c 200 err.txt)" [ -s a.json ]
"${run_limited[@]}" "${sim[@]}" "$f" -o b.png --config sub/d.toml --stats b.json 2>err.txt
check "run from the dump: exit $?: $(head -c 200 err.txt)" [ -s b.json ]
check "the run from the dump reads the same timing file (sim_time_s $(json a.json .sim_time_s) vs $(json b.json .sim_time_s))" \
    [ "$(json a.json .sim_time_s)" = "$(json b.json .sim_time_s)" ]
check "the run from the dump has the same timing table" \
    [ "$(json a.json .config.timing)" = "$(json b.json .config.timing)" ]
"$BUILD/torusrt-sim" --dump-config --config sub/d.toml >sub/dd.toml 2>err.txt
check "a dump of a dump is the same file: $(diff sub/d.toml sub/dd.toml | head -c 300)" cmp -s sub/d.toml sub/dd.toml
"${report[@]}" machine a.json --compare sub/d.toml >cmp.txt 2>&1
check "report machine --compare: the run and its dump are the same machine: $(head -c 300 cmp.txt)" [ $? -eq 0 ]
(cd sub && "$BUILD/torusrt-sim" --dump-config --ips 2 --timing lit.timing >../other.toml)
"${report[@]}" machine a.json --compare other.toml >cmp.txt 2>&1
check "report machine --compare: another timing file of the same name is a difference (exit $?)" \
    grep -q "timing" cmp.txt

# The map file: the same, with a map of the same name beside the dump that maps otherwise.
"${run_limited[@]}" "${sim[@]}" "$f" -o m.png --ips 2 --map block --write-map own.map 2>err.txt
check "--write-map: exit $?: $(head -c 200 err.txt)" [ -s own.map ]
"${run_limited[@]}" "${sim[@]}" "$f" -o m.png --ips 2 --map cyclic --write-map sub/own.map 2>err.txt
check "--write-map into sub: exit $?: $(head -c 200 err.txt)" [ -s sub/own.map ]
"$BUILD/torusrt-sim" --dump-config --ips 2 --map-file own.map >sub/m.toml 2>err.txt
check "dump with a relative --map-file: exit $?: $(head -c 200 err.txt)" [ -s sub/m.toml ]
"${run_limited[@]}" "${sim[@]}" "$f" -o c.png --ips 2 --map-file own.map --stats c.json 2>err.txt
"${run_limited[@]}" "${sim[@]}" "$f" -o d.png --config sub/m.toml --stats d.json 2>err.txt
check "the run from the dump reads the same map file: exit $?: $(head -c 200 err.txt)" \
    [ "$(json c.json .sim_time_s)" = "$(json d.json .sim_time_s)" ]
"$BUILD/torusrt-sim" --dump-config --config sub/m.toml >sub/mm.toml 2>err.txt
check "a dump of a dump (map file) is the same file" cmp -s sub/m.toml sub/mm.toml
finish
