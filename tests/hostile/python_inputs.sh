#!/usr/bin/env bash
# python_inputs.sh - what the Python and shell tools of experiments/ read, and the outputs their
# commands name: the files a --config machine file names (timing=, map-file=) are inputs of
# compare-mappings and the sweep and part of a sweep point; a stream (/dev/stdout) as --out is
# refused before any run; output options after `--` (compare-mappings) or among a sweep's fixed
# options are refused; run_point.sh's outputs are never its command's inputs; the backend's
# --runs is never its point list; a point JSON with a number that is not finite, or not the one
# its run wrote, runs again; sweep axis values of one point name, or empty, are refused before
# anything is written; report and the backend refuse a device, a FIFO or text that is not UTF-8
# naming the file; report compare is two-sided; a study's --results must name a folder.
#
# Usage (CTest runs it so): bash tests/hostile/python_inputs.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
for tool in python3 parallel gnuplot jq; do
    command -v "$tool" >/dev/null || { echo "$TEST_NAME: $tool is not installed; skipped"; exit 77; }
done
time_limit 30  # a FIFO or a device read without a bound hangs: killed, a failure
EXP=$SRC/experiments
export TORUSRT_BUILD=$BUILD
scene1=$(source_scene paper-image1) || exit 1
cd "$TMP" || exit 1
cp "$scene1" s1.nff
small=(--size 8x8)

# exits STATUS NAME PATTERN COMMAND...: exit STATUS, stderr matching PATTERN, no traceback; the
# command's output in NAME.out and NAME.err (a / of NAME as _).
exits() {
    local status=$1 name=$2 pattern=$3 f=${2//\//_}
    shift 3
    "${run_limited[@]}" "$@" >"$f.out" 2>"$f.err" </dev/null
    local rc=$?
    check "$name: exit $rc, expected $status: $(head -c 300 "$f.err")" [ "$rc" -eq "$status" ]
    check "$name: the message names it ('$pattern'): $(head -c 300 "$f.err")" grep -q -e "$pattern" "$f.err"
    check "$name: no traceback" test "$(grep -c Traceback "$f.err")" -eq 0
}
refused() { exits 2 "$@"; }
failed() { exits 1 "$@"; }
differ() { ! cmp -s "$1" "$2"; }
# kept NAME FILE KEPT: FILE still holds KEPT's bytes.
kept() { check "$1: $2 changed" cmp -s "$2" "$3"; }

# A machine file naming a timing file and a map file beside it (read from the machine file's folder).
mkdir cfg
printf 'link 50\n' >cfg/n.timing && cp cfg/n.timing keep.timing
printf 'torusrt-map 1\n' >cfg/w.map && cp cfg/w.map keep.map
printf 'timing="n.timing"\n' >cfg/m.toml
printf 'map-file="w.map"\n' >cfg/mf.toml

# ---- compare-mappings ----------------------------------------------------------------------
cm=("$EXP/compare-mappings" --build "$BUILD" --map "block,cyclic")
refused "cm --out a --config's timing" "is the --config cfg/m.toml's timing file" \
    "${cm[@]}" s1.nff --out cfg/n.timing -- --ips 2 "${small[@]}" --config cfg/m.toml
kept "cm --out a --config's timing" cfg/n.timing keep.timing
refused "cm --out a --config's map-file" "is the --config cfg/mf.toml's map-file file" \
    "${cm[@]}" s1.nff --out cfg/w.map -- --ips 2 "${small[@]}" --config=cfg/mf.toml
kept "cm --out a --config's map-file" cfg/w.map keep.map
echo keep >log.txt
"${run_limited[@]}" "${cm[@]}" s1.nff --out /dev/stdout -- --ips 2 "${small[@]}" >>log.txt 2>cm-stdout.err </dev/null
rc=$?
check "cm --out /dev/stdout >> log: exit $rc, expected 2" [ "$rc" -eq 2 ]
check "cm --out /dev/stdout: named: $(head -c 300 cm-stdout.err)" grep -q "/dev/stdout': is a stream" cm-stdout.err
check "cm --out /dev/stdout: log.txt keeps its line" [ "$(head -n 1 log.txt)" = keep ]
refused "cm --out /dev/stderr" "is a stream" "${cm[@]}" s1.nff --out /dev/stderr -- --ips 2 "${small[@]}"
refused "cm -- --write-map" "--write-map after --: every run would write it into one file" \
    "${cm[@]}" s1.nff --out cm.png -- --ips 2 "${small[@]}" --write-map wm.txt
refused "cm -- --vcd=" "--vcd after --" "${cm[@]}" s1.nff --out cm.png -- --ips 2 "${small[@]}" --vcd=v.vcd
refused "cm -- -o" "-o after --: every run would write it" "${cm[@]}" s1.nff --out cm.png -- --ips 2 -o x.png
refused "cm -- --stats the --out" "--stats after --" "${cm[@]}" s1.nff --out cm.png -- --ips 2 --stats cm.png
refused "cm -- --t1" "--t1 after --: compare-mappings gives" "${cm[@]}" s1.nff --out cm.png -- --ips 2 --t1 1
refused "cm -- --map" "--map after --" "${cm[@]}" s1.nff --out cm.png -- --ips 2 --map cyclic
check "cm: refused, nothing written" [ ! -e wm.txt ] && [ ! -e v.vcd ] && [ ! -e x.png ] && [ ! -e cm.png ]

# ---- sweep ---------------------------------------------------------------------------------
sweep=("$EXP/sweep" --build "$BUILD")
# swept NAME OUT ARGS...: a sweep of s1.nff that must succeed.
swept() {
    local name=$1 out=$2
    shift 2
    "${run_limited[@]}" "${sweep[@]}" s1.nff --out "$out" "$@" >"$name.out" 2>"$name.err" </dev/null
    local rc=$?
    check "$name: exit $rc: $(tail -c 300 "$name.err")" [ "$rc" -eq 0 ]
    return $rc
}
# The timing file a --config names changes: the point runs again, its figures the fresh ones.
if swept "sweep with link 50" sw --axis ips=2 -- "${small[@]}" --config "$TMP/cfg/m.toml"; then
    cp sw/sweep.csv sw50.csv
    printf 'link 50000\n' >cfg/n.timing
    swept "sweep with link 50000" sw --axis ips=2 -- "${small[@]}" --config "$TMP/cfg/m.toml" &&
        check "sweep: the --config's timing changed: the point runs again" \
            grep -q "(0 done before)" "sweep with link 50000.out"
    swept "sweep with link 50000, fresh" sw-fresh --axis ips=2 -- "${small[@]}" --config "$TMP/cfg/m.toml" &&
        check "sweep: the --config's timing changed: the CSV is a fresh sweep's" \
            cmp -s <(nowall sw/sweep.csv) <(nowall sw-fresh/sweep.csv)
    check "sweep: the two timings give two times" differ <(nowall sw/sweep.csv) <(nowall sw50.csv)
fi
printf 'link 50\n' >cfg/n.timing
refused "sweep: --vcd among the fixed options" "--vcd among the fixed options" \
    "${sweep[@]}" s1.nff --axis ips=1,2 --out s10 -- "${small[@]}" --vcd "$TMP/v.vcd"
refused "sweep: --write-map among the fixed options" "--write-map among the fixed options" \
    "${sweep[@]}" s1.nff --axis ips=1,2 --out s10 -- "${small[@]}" --write-map "$TMP/wm.txt"
check "sweep: fixed outputs refused, nothing written" [ ! -e s10/points.list ] && [ ! -e v.vcd ] && [ ! -e wm.txt ]
mkdir -p a && cp cfg/n.timing a/t.timing && cp cfg/n.timing a_t.timing
refused "sweep: two values of one point name" "have one name, timing_a_t.timing" \
    "${sweep[@]}" s1.nff --axis timing=a/t.timing,a_t.timing --out s14 -- "${small[@]}"
refused "sweep: an empty axis value" "an empty value" "${sweep[@]}" s1.nff --axis ips=1,,2 --out s14 -- "${small[@]}"
check "sweep: axes refused, nothing written" [ ! -e s14/points.tsv ] && [ ! -e s14/points.list ]

# A point JSON edited after its run: a number that is not finite, another point's report.
if swept "sweep ips=1,2" s16 --axis ips=1,2 -- "${small[@]}"; then
    cp s16/sweep.csv s16.csv
    printf '{"status":"ok","sim_time_s":1e999,"config":{}}' >s16/points/ips_2.json
    swept "sweep: an infinite time" s16 --axis ips=1,2 -- "${small[@]}" &&
        check "sweep: an infinite time runs again: $(head -c 200 'sweep: an infinite time.err')" \
            grep -q "(1 done before)" "sweep: an infinite time.out"
    check "sweep: an infinite time: the CSV is whole" cmp -s <(nowall s16/sweep.csv) <(nowall s16.csv)
    cp s16/points/ips_1.json s16/points/ips_2.json
    swept "sweep: another point's JSON" s16 --axis ips=1,2 -- "${small[@]}" &&
        check "sweep: another point's JSON is named: $(head -c 200 'sweep: another point'"'"'s JSON.err')" \
            grep -q "ips_2.json: not the JSON its run wrote" "sweep: another point's JSON.err"
    check "sweep: another point's JSON: the CSV is whole" cmp -s <(nowall s16/sweep.csv) <(nowall s16.csv)
fi

# ---- run_point.sh --------------------------------------------------------------------------
for case in "s.nff s.nff" "q.json q.png" "p.json p.log"; do
    set -- $case
    cp s1.nff "$2"
    refused "run_point $1 over the scene $2" "is the argument file $2, an input" \
        "$EXP/run_point.sh" "$1" -- "$BUILD/torusrt-sim" "$2" "${small[@]}" --t1 1
    kept "run_point $1 over the scene $2" "$2" s1.nff
done
cp cfg/n.timing keep.timing
refused "run_point over a --config's timing" "is the --config cfg/m.toml's timing file" \
    "$EXP/run_point.sh" cfg/n.timing -- "$BUILD/torusrt-sim" s1.nff "${small[@]}" --t1 1 --config cfg/m.toml
kept "run_point over a --config's timing" cfg/n.timing keep.timing

# ---- the backend ---------------------------------------------------------------------------
mkdir bk
printf '%s\t%s\n' "$TMP/bk/a" "echo 1 > $TMP/bk/a" >l.list && cp l.list keep.list
backend=(python3 "$EXP/backend" run --state "$TMP/st")
refused "backend --runs the list" "--runs '.*l.list': is the point list file" "${backend[@]}" --runs l.list l.list
kept "backend --runs the list" l.list keep.list
check "backend --runs the list: nothing ran" [ ! -e bk/a ]
mkfifo list.fifo
refused "backend a device as the list" "the point list '/dev/zero': is a character device" "${backend[@]}" /dev/zero
refused "backend a FIFO as the list" "the point list 'list.fifo': is a FIFO" "${backend[@]}" list.fifo
printf '\xff\xfe\n' >bin.list
refused "backend a list not UTF-8" "bin.list': not UTF-8" "${backend[@]}" bin.list

# ---- report --------------------------------------------------------------------------------
report=(python3 "$EXP/report")
failed "report compare a missing folder" "nonexistent: no such results folder" \
    "${report[@]}" compare nonexistent "$EXP/results"
failed "report compare a missing folder, the other way" "nonexistent: no such results folder" \
    "${report[@]}" compare "$EXP/results" nonexistent
cp -r "$EXP/results" res-a && cp -r "$EXP/results" res-b
extra=$(cd res-a && find . -name 'fig*.csv' | head -n 1)
rm "res-a/$extra"
"${run_limited[@]}" "${report[@]}" compare res-a res-b >compare.out 2>compare.err </dev/null
rc=$?
check "report compare: a CSV only in the new folder: exit $rc, expected 1" [ "$rc" -eq 1 ]
check "report compare: a CSV only in the new folder: named: $(head -c 300 compare.out)" \
    grep -q "${extra#./}: not in .*res-a" compare.out
failed "report machine /dev/zero" "report '/dev/zero': is a character device" "${report[@]}" machine /dev/zero
failed "report machine a FIFO" "report 'list.fifo': is a FIFO" "${report[@]}" machine list.fifo
printf '[1]' >g.json
failed "report machine an array" "g.json: not a JSON report (a list" "${report[@]}" machine g.json
if [ -s s16/points/ips_1.json ]; then
    cp s16/points/ips_1.json a.json
    failed "report machine --compare /dev/zero" "--compare '/dev/zero': is a character device" \
        "${report[@]}" machine a.json --compare /dev/zero
    failed "report machine --compare a FIFO" "--compare 'list.fifo': is a FIFO" \
        "${report[@]}" machine a.json --compare list.fifo
    failed "report machine --compare not UTF-8" "--compare 'bin.list': not UTF-8" \
        "${report[@]}" machine a.json --compare bin.list
    jq '.config.options.map = null' a.json >null.json
    failed "report machine a null option" "config.options.map: null" "${report[@]}" machine null.json
    check "report machine a null option: no machine written" [ ! -s "report machine a null option.out" ]
    jq '.config.options.frob = "1"' a.json >frob.json
    failed "report machine an unknown option" "config.options.frob: not a machine option" \
        "${report[@]}" machine frob.json
    failed "report collect a sweep folder" "points.tsv:1: 2 columns" "${report[@]}" collect s16
fi

# ---- a study's --results -------------------------------------------------------------------
cp -r "$EXP" copy
refused "buffers --results ''" "--results: an empty value" bash copy/buffers/study.sh --quick --results ''
refused "buffers --results with no value" "--results needs a value" bash copy/buffers/study.sh --quick --results
check "buffers --results '': nothing written" [ ! -e copy/buffers/results-quick ]

finish
