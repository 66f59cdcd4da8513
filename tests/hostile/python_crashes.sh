#!/usr/bin/env bash
# python_crashes.sh - the Python tools of experiments/ end with a message, never a traceback, on:
# - a stopping signal (INT, QUIT, USR1, TERM, ...): `PROGRAM: stopped by SIGNAME`, 128 + N, no
#   temporary folder or file left (compare-mappings); a sweep stopped by TERM or INT stops its
#   points too;
# - standard output closed (>&-): `standard output: cannot write: Bad file descriptor`, exit 1
#   (compare-mappings, the sweep, report machine, report compare, the backend), nothing made;
# - a byte that is not UTF-8 in torusrt-sim's message (a scene's name): shown as \xNN;
# - a CSV row with fewer fields than its header (report compare, report reproduction), and a
#   report whose config.option_order is null (report machine): the file, line or field named;
# - a run's report compare-mappings cannot read (not an object, a field missing): named, exit 1;
# - the sweep's options in the --opt=value form, and a --y field no report has or one that is
#   not a number: refused before any point runs, no --out made.
#
# Usage (CTest runs it so): bash tests/hostile/python_crashes.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
for tool in python3 parallel gnuplot; do
    command -v "$tool" >/dev/null || { echo "$TEST_NAME: $tool is not installed; skipped"; exit 77; }
done
time_limit 90
EXP=$SRC/experiments
export TORUSRT_BUILD=$BUILD
scene1=$(source_scene paper-image1) || exit 1
mkdir "$TMP/work" "$TMP/tmpdir" && cd "$TMP/work" || exit 1
export TMPDIR=$TMP/tmpdir  # compare-mappings' temporary folder, to see it removed
cp "$scene1" s.nff
small=(--size 8x8)

# no_traceback NAME FILE: FILE (a command's standard error) holds no Python traceback.
no_traceback() { check "$1: no traceback: $(head -c 300 "$2")" test "$(grep -c 'Traceback' "$2")" -eq 0; }
# ends STATUS NAME PATTERN FILE RC: exit RC is STATUS, FILE matches PATTERN, no traceback.
ends() {
    check "$2: exit $5, expected $1: $(head -c 300 "$4")" [ "$5" -eq "$1" ]
    check "$2: the message ('$3'): $(head -c 300 "$4")" grep -q -e "$3" "$4"
    no_traceback "$2" "$4"
}
# default_signals COMMAND...: COMMAND (the same process) with INT and QUIT at their default
# action (a shell starts a background command ignoring them), as from a terminal.
default_signals=(python3 -c 'import os, signal, sys
for s in (signal.SIGINT, signal.SIGQUIT):
    signal.signal(s, signal.SIG_DFL)
os.execvp(sys.argv[1], sys.argv[1:])')
# wait_for_sim PATTERN: until a torusrt-sim whose command line matches PATTERN runs (20 s at most).
wait_for_sim() {
    local _
    for _ in $(seq 200); do
        pgrep -f "torusrt-sim.*$1" >/dev/null && return 0
        sleep 0.1
    done
    return 1
}
# sims_gone PATTERN: no torusrt-sim whose command line matches PATTERN runs (10 s at most).
sims_gone() {
    local _
    for _ in $(seq 100); do
        pgrep -f "torusrt-sim.*$1" >/dev/null || return 0
        sleep 0.1
    done
    return 1
}

# ---- compare-mappings on a stopping signal: a message, 128 + N, no temporary ---------------
for sig in INT QUIT USR1 TERM; do
    "${default_signals[@]}" "$EXP/compare-mappings" s.nff --out "c-$sig.png" -- --ips 4x4 --size 600x600 \
        >/dev/null 2>"cm-$sig.err" </dev/null &
    pid=$!
    check "cm $sig: its run started" wait_for_sim "$TMPDIR/compare-mappings"
    kill -s "$sig" "$pid"
    wait "$pid"
    rc=$?
    ends $((128 + $(kill -l "$sig"))) "cm $sig" "compare-mappings: stopped by SIG$sig" "cm-$sig.err" "$rc"
    check "cm $sig: no temporary folder left: $(ls -A "$TMPDIR")" test -z "$(ls -A "$TMPDIR")"
    made=$(compgen -G "*c-$sig.png*")
    check "cm $sig: no image, no temporary beside it: $made" test -z "$made"
    sims_gone "$TMPDIR/compare-mappings" || fail "cm $sig: its run goes on"
done

# ---- a sweep stopped by TERM or Ctrl-C stops its points (large images: no point may finish --
# ---- before the signal, however slow the machine) ------------------------------------------
for sig in TERM INT; do
    "${default_signals[@]}" "$EXP/sweep" s.nff --axis ips=4x4,2x2 --out "sw$sig" -j 2 -- --size 1600x1600 \
        >"sw$sig.out" 2>"sw$sig.err" </dev/null &
    pid=$!
    check "sweep $sig: its points started" wait_for_sim "$TMP/work/sw$sig/points"
    kill -s "$sig" "$pid"
    wait "$pid"
    rc=$?
    ends $((128 + $(kill -l "$sig"))) "sweep $sig" "sweep: stopped by SIG$sig" "sw$sig.err" "$rc"
    check "sweep $sig: its points stopped" sims_gone "$TMP/work/sw$sig/points"
    left=""
    for f in "sw$sig"/points/* "sw$sig"/points/.[!.]*; do  # a point's temporary starts with '.'
        if [ -e "$f" ] && [ "${f%.log}" = "$f" ]; then left+="$f "; fi
    done
    check "sweep $sig: no point's file left but its log: $left" test -z "$left"
done

# ---- standard output closed ------------------------------------------------------------------
"$BUILD/torusrt-sim" s.nff -q -o a.png "${small[@]}" --stats a.json </dev/null
check "a report to read: exit $?" [ -s a.json ]
EBADF="standard output: cannot write: Bad file descriptor"
closed() {
    local name=$1
    shift
    "${run_limited[@]}" "$@" >&- 2>"$name.err" </dev/null
    ends 1 "$name >&-" "$EBADF" "$name.err" $?
}
closed cm "$EXP/compare-mappings" s.nff --out cclosed.png -- --ips 2 "${small[@]}"
check "cm >&-: no image" [ ! -e cclosed.png ]
closed sweep "$EXP/sweep" s.nff --axis ips=1,2 --out swclosed -- "${small[@]}"
check "sweep >&-: no --out folder" [ ! -e swclosed ]
closed machine python3 "$EXP/report" machine a.json
mkdir -p CA CB
printf 'scene,n,status,sim_time_s\na,1,ok,1\n' >CA/fig7.csv
cp CA/fig7.csv CB/fig7.csv
closed compare python3 "$EXP/report" compare CA CB
printf '/dev/null\ttrue\n' >list.tsv
closed backend python3 "$EXP/backend" run --state stclosed list.tsv
check "backend >&-: no --state folder" [ ! -e stclosed ]

# ---- a byte that is not UTF-8 in torusrt-sim's message ---------------------------------------
printf 's 0 0 0 1\n\0' >$'\xffb.nff'
"${run_limited[@]}" "$EXP/compare-mappings" $'\xffb.nff' --out cff.png -- --ips 2 "${small[@]}" \
    >/dev/null 2>ff.err </dev/null
ends 1 "cm on a name with a 0xff byte" '\\xffb.nff:2: binary data' ff.err $?

# ---- a CSV row with fewer fields than its header --------------------------------------------
printf 'scene,n,status,sim_time_s\na\n' >CB/fig7.csv
"${run_limited[@]}" python3 "$EXP/report" compare CA CB >/dev/null 2>short.err </dev/null
ends 1 "compare a short row" "CB/fig7.csv: line 2: 1 fields, the header has 4" short.err $?
mkdir RES && cp -r "$SRC/experiments/results/fitted" RES/
sed -i '3s/^\([^,]*\),.*/\1/' RES/fitted/fig7.csv
"${run_limited[@]}" python3 "$EXP/report" reproduction RES --doc "$PWD/rep/r.md" >/dev/null 2>rep.err </dev/null
ends 1 "reproduction a short row" "RES/fitted/fig7.csv: line 3: 1 fields, the header has" rep.err $?
check "reproduction a short row: no page" [ ! -e rep/r.md ]

# ---- report machine on a report whose config.option_order is null ---------------------------
python3 -c "import json; d = json.load(open('a.json')); d['config']['option_order'] = None
json.dump(d, open('n.json', 'w'))"
"${run_limited[@]}" python3 "$EXP/report" machine n.json >n.toml 2>n.err </dev/null
ends 1 "machine option_order null" "n.json: config.option_order: null" n.err $?

# ---- the sweep's --opt=value form; --y checked before any point runs --------------------------
"${run_limited[@]}" "$EXP/sweep" s.nff --axis=ips=1,2 --out=sweq --y=efficiency_t1 --columns=t1_s \
    -- "${small[@]}" >sweq.out 2>sweq.err </dev/null
check "sweep --out=DIR: exit $?: $(head -c 300 sweq.err)" [ -s sweq/sweep.csv ]
check "sweep --columns=t1_s --y=efficiency_t1: the CSV's columns: $(head -1 sweq/sweep.csv)" \
    [ "$(head -1 sweq/sweep.csv)" = "ips,status,t1_s,efficiency_t1" ]
"${run_limited[@]}" "$EXP/sweep" s.nff --axis ips=1,2 --out swy --y nosuch -- "${small[@]}" \
    >swy.out 2>swy.err </dev/null
ends 2 "sweep --y nosuch" "no such JSON field .*: nosuch " swy.err $?
check "sweep --y nosuch: named once: $(cat swy.err)" [ "$(grep -o nosuch swy.err | wc -l)" -eq 1 ]
check "sweep --y nosuch: no point run, no --out made" [ ! -e swy ]
for y in status scene config.mapping; do  # fields that are not numbers: nothing to plot
    "${run_limited[@]}" "$EXP/sweep" s.nff --axis ips=1,2 --out "swy$y" --y "$y" -- "${small[@]}" \
        >/dev/null 2>"swy$y.err" </dev/null
    ends 2 "sweep --y $y" "--y $y: .*not a number to plot" "swy$y.err" $?
    check "sweep --y $y: no point run, no --out made" [ ! -e "swy$y" ]
done
"${run_limited[@]}" "$EXP/sweep" s.nff --axis ips=1,2 --out swy --columns t1_s,t1_s -- "${small[@]}" \
    >swy.out 2>swy.err </dev/null
ends 2 "sweep --columns given twice" "'t1_s' is given twice" swy.err $?
check "sweep --columns given twice: no --out made" [ ! -e swy ]

# ---- memory the system refuses (ulimit -v): a message and exit 1, never a MemoryError traceback --
mkdir -p MA MB && printf 'scene,n,status,sim_time_s\na,1,ok,1\n' >MA/fig7.csv && cp MA/fig7.csv MB/
tracebacks=0
for limit in 18000 20000 22000 24000 28000 32000; do
    for tool in "python3 $EXP/report compare MA MB" "python3 $EXP/backend run --state mst nosuch.list" \
        "$EXP/compare-mappings s.nff --map block --out mcm.png -- --size 8x8"; do
        # shellcheck disable=SC2086  # the command splits at its spaces
        (ulimit -v "$limit" && exec $tool) >/dev/null 2>mem.err </dev/null
        if grep -q "Traceback" mem.err; then
            tracebacks=$((tracebacks + 1))
            echo "ulimit -v $limit: $tool: $(tail -n 2 mem.err | tr '\n' ' ' | head -c 200)"
        fi
    done
done
check "Python tools under ulimit -v 18-32 MB: runs that ended in a traceback: $tracebacks of 18" [ "$tracebacks" -eq 0 ]

# ---- compare-mappings on a report it cannot read (another build, not torusrt-sim) -----------
mkdir -p fake
for report in '[1,2]' '{"nodes": 1e999, "status": "ok"}' \
    '{"sim_time_s": 1, "t1_s": 1, "efficiency": 1, "per_ip": [{"node": "x", "busy_s": 1}]}'; do
    printf '#!/bin/sh\nfor a; do [ "$prev" = --stats ] && printf %%s %q > "$a"; prev=$a; done\nexit 0\n' \
        "$report" >fake/torusrt-sim
    chmod +x fake/torusrt-sim
    "$EXP/compare-mappings" s.nff --map block --out fcm.png --build fake >/dev/null 2>fcm.err </dev/null
    rc=$?
    check "compare-mappings, report $report: exit 1 (got $rc)" [ "$rc" -eq 1 ]
    check "compare-mappings, report $report: says why: $(head -c 200 fcm.err)" \
        grep -q "compare-mappings: --map block: the report of fake/torusrt-sim" fcm.err
    no_traceback "compare-mappings, report $report" fcm.err
    check "compare-mappings, report $report: no picture" [ ! -e fcm.png ]
done
finish
