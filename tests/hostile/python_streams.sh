#!/usr/bin/env bash
# python_streams.sh - the Python and shell tools of experiments/ never write into their inputs
# through their own standard output or error, read a hand-made point JSON without a traceback,
# and leave no command running when run_point.sh alone is stopped:
# - `>> INPUT` and `2>> INPUT` (the scene, a file after --, a --compare machine file, a point
#   list) for compare-mappings, the sweep, report machine, run_point.sh and the backend: exit 2
#   before anything runs, the input unchanged (also when the command line is wrong, and so would
#   give a usage message); and `>> FILE` or `2>> FILE` for a file inside a folder the command
#   names (report compare's CSVs and a log beside them, a sweep's point JSON, id and a new
#   point's log, sweep-collect's points.tsv), run_point.sh's own OUT.log, and a study's scene or
#   a file of its --results folder;
# - a point JSON nested 100000 deep: the sweep's resume runs the point again, report machine
#   names the file as not a report (exit 1), no RecursionError traceback;
# - TERM, HUP, USR1, USR2 or ALRM sent to run_point.sh's shell alone: its command is stopped too,
#   the script says `run_point: stopped by SIGNAME` and ends with 128 + the signal, and no
#   temporary (.NAME.tmp.HOST.PID.*) stays.
#
# Usage (CTest runs it so): bash tests/hostile/python_streams.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
for tool in python3 parallel gnuplot jq; do
    command -v "$tool" >/dev/null || { echo "$TEST_NAME: $tool is not installed; skipped"; exit 77; }
done
time_limit 60
EXP=$SRC/experiments
export TORUSRT_BUILD=$BUILD
scene1=$(source_scene paper-image1) || exit 1
cd "$TMP" || exit 1
small=(--size 8x8)
cp "$scene1" keep.nff
"$BUILD/torusrt-sim" keep.nff -q -o a.png "${small[@]}" --stats a.json </dev/null
"$BUILD/torusrt-sim" --dump-config --ips 2 >keep.toml </dev/null
printf '%s\ttrue\n' "$TMP/done.json" >keep.list

# appended STREAM NAME FILE KEEP PATTERN COMMAND...: COMMAND with standard output (STREAM 1) or
# error (2) appended to FILE: exit 2, FILE still equal to KEEP and, with standard output, the
# message on standard error matching PATTERN.
appended() {
    local stream=$1 name=$2 file=$3 keep=$4 pattern=$5 f=$TMP/${2//[\/ \']/_}
    shift 5
    if [ "$stream" = 1 ]; then
        "${run_limited[@]}" "$@" >>"$file" 2>"$f.err" </dev/null
    else
        "${run_limited[@]}" "$@" 2>>"$file" >"$f.out" </dev/null
    fi
    local rc=$?
    check "$name: exit $rc, expected 2" [ "$rc" -eq 2 ]
    check "$name: $file changed: $(cmp "$keep" "$file" 2>&1 | head -c 200)" cmp -s "$keep" "$file"
    [ "$stream" = 2 ] || check "$name: the message names it: $(head -c 300 "$f.err")" grep -q "$pattern" "$f.err"
}
# into STREAM NAME INPUT COMMAND...: appended to INPUT, a copy of keep.EXT put in place first.
into() {
    local input=$3
    cp "keep.${input##*.}" "$input"
    appended "$1" "$2" "$input" "keep.${input##*.}" "standard output is redirected to .*$input, an input" "${@:4}"
}
cm=("$EXP/compare-mappings" --build "$BUILD" --map block,cyclic --out c.png)
into 1 "cm >> scene" s.nff "${cm[@]}" s.nff -- --ips 2 "${small[@]}"
into 2 "cm 2>> scene" s.nff "${cm[@]}" s.nff --frobnicate
into 1 "cm >> --config after --" m.toml "${cm[@]}" keep.nff -- --config m.toml "${small[@]}"
check "cm: no image written by a refused run" [ ! -e c.png ]
into 1 "sweep >> scene" s.nff "$EXP/sweep" --build "$BUILD" s.nff --axis ips=1 --out sw -- "${small[@]}"
into 2 "sweep 2>> scene" s.nff "$EXP/sweep" --build "$BUILD" s.nff --axis ips=1 --out sw -- "${small[@]}"
into 2 "sweep 2>> scene, unknown option" s.nff "$EXP/sweep" --build "$BUILD" s.nff --frobnicate
check "sweep: no --out folder made by a refused run" [ ! -e sw ]
into 1 "report machine --compare >> it" m.toml python3 "$EXP/report" machine a.json --compare m.toml
into 2 "report machine 2>> it, bad option" m.toml python3 "$EXP/report" machine a.json --compare m.toml --frob
into 2 "run_point 2>> scene" s.nff "$EXP/run_point.sh" rp/p.json -- "$BUILD/torusrt-sim" s.nff --ips zz
into 1 "run_point >> scene" s.nff "$EXP/run_point.sh" rp/p.json -- "$BUILD/torusrt-sim" s.nff "${small[@]}"
check "run_point: nothing written by a refused run" [ ! -e rp/p.json ] && [ ! -e rp/p.log ]
into 1 "backend >> its list" l.list python3 "$EXP/backend" run --state st l.list
check "backend: no --state folder made by a refused run" [ ! -e st ]

# ---- a file inside a folder the command works on (a results folder, a sweep's --out) ---------
# in_folder STREAM NAME FILE COMMAND...: appended to FILE, which lies in a folder COMMAND names.
in_folder() {
    local keep=$TMP/${2//[\/ \']/_}.keep
    cp "$3" "$keep"
    appended "$1" "$2" "$3" "$keep" "standard output is redirected to .*$3, in the .*folder" "${@:4}"
}
mkdir A B
printf 'scene,n,status,sim_time_s\na,1,ok,1\n' >A/fig7.csv
printf 'scene,n,status,sim_time_s\na,1,ok,2\n' >B/fig7.csv
in_folder 1 "report compare >> a CSV it reads" A/fig7.csv python3 "$EXP/report" compare A B
in_folder 2 "report compare 2>> a CSV it reads" B/fig7.csv python3 "$EXP/report" compare A B
echo "my notes" >A/notes.log
in_folder 1 "report compare >> a log in the folder" A/notes.log python3 "$EXP/report" compare A B
"${run_limited[@]}" "$EXP/sweep" --build "$BUILD" keep.nff --axis ips=1,2 --out R -- "${small[@]}" \
    >/dev/null 2>R.err </dev/null
check "sweep into R: exit $?: $(head -c 300 R.err)" [ -s R/points/ips_1.json ]
for stream in 1 2; do
    in_folder "$stream" "sweep $stream>> a point's JSON" R/points/ips_1.json \
        "$EXP/sweep" --build "$BUILD" keep.nff --axis ips=1,2 --out R -- "${small[@]}"
    in_folder "$stream" "sweep $stream>> a point's id" R/points/ips_1.id \
        "$EXP/sweep" --build "$BUILD" keep.nff --axis ips=1,2 --out R -- "${small[@]}"
done
in_folder 1 "report sweep-collect >> its points.tsv" R/points.tsv \
    python3 "$EXP/report" sweep-collect --out R --columns "" --y sim_time_s
# A point's own log, which its run replaces: a new point's in a sweep, run_point.sh's.
echo "my notes" >R/points/ips_4.log
in_folder 1 "sweep >> a new point's log" R/points/ips_4.log \
    "$EXP/sweep" --build "$BUILD" keep.nff --axis ips=1,2,4 --out R -- "${small[@]}"
mkdir -p rp && echo "my notes" >rp/g.log
into_own() {  # run_point.sh's refusal names the file (an input of its check), exit 2, the file kept
    "${run_limited[@]}" "$EXP/run_point.sh" rp/g.json -- "$BUILD/torusrt-sim" keep.nff "${small[@]}" >>rp/g.log \
        2>rp.err </dev/null
    local rc=$?
    check "run_point >> the point's own log: exit $rc, expected 2" [ "$rc" -eq 2 ]
    check "run_point >> the point's own log: kept" [ "$(cat rp/g.log)" = "my notes" ]
}
into_own

# ---- a study's streams: a scene it reads, a file of the results folder it is given ------------
# (a copy of the tree: a failed check must not touch the source's scenes)
mkdir -p tree && cp -r "$SRC/experiments" "$SRC/scenes" tree/
mkdir -p Rq && echo '{}' >Rq/f.json
in_folder 1 "study >> a scene it reads" tree/scenes/paper-image1.nff \
    bash tree/experiments/buffers/study.sh --quick --build "$BUILD" --results "$TMP/Rq"
in_folder 2 "study 2>> a file of its results folder" Rq/f.json \
    bash tree/experiments/buffers/study.sh --quick --build "$BUILD" --results "$TMP/Rq"
check "the refused studies ran nothing: $(ls -A Rq | tr '\n' ' ')" [ "$(ls -A Rq)" = f.json ]

# ---- a point JSON nested 100000 deep ------------------------------------------------------
deep() { python3 -c "print('{\"a\":' * 100000 + '1' + '}' * 100000)"; }
"${run_limited[@]}" "$EXP/sweep" --build "$BUILD" keep.nff --axis ips=1 --out dj -- "${small[@]}" \
    >/dev/null 2>dj.err </dev/null
check "deep JSON: the first sweep: exit $?: $(head -c 300 dj.err)" [ -s dj/points/ips_1.json ]
deep >dj/points/ips_1.json
"${run_limited[@]}" "$EXP/sweep" --build "$BUILD" keep.nff --axis ips=1 --out dj -- "${small[@]}" \
    >/dev/null 2>dj.err </dev/null
rc=$?
check "deep JSON: the sweep's resume: exit $rc: $(grep -v gnuplot dj.err | head -c 300)" [ "$rc" -eq 0 ]
check "deep JSON: the sweep's resume: no traceback" test "$(grep -c 'Traceback\|RecursionError' dj.err)" -eq 0
check "deep JSON: the sweep's resume names the file as not a report: $(head -c 300 dj.err)" \
    grep -q "ips_1.json: not a JSON report" dj.err
check "deep JSON: the point run again" jq -e .sim_time_s dj/points/ips_1.json >/dev/null
deep >deep.json
python3 "$EXP/report" machine deep.json >/dev/null 2>deep.err </dev/null
rc=$?
check "deep JSON: report machine: exit $rc, expected 1" [ "$rc" -eq 1 ]
check "deep JSON: report machine names it: $(head -c 300 deep.err)" grep -q "deep.json: not a JSON report" deep.err
check "deep JSON: report machine: no traceback" test "$(grep -c 'Traceback\|RecursionError' deep.err)" -eq 0

# ---- run_point.sh stopped alone: its command stops too, no temporary stays -------------------
# A command that makes the temporaries run_point.sh names (-o and --stats), notes its process id
# and waits: what a long torusrt-sim run does until it commits.
cat >slow.sh <<'EOF'
#!/usr/bin/env bash
while [ $# -gt 0 ]; do
    case $1 in -o|--stats) : >"$2"; shift ;; esac
    shift
done
echo $$ >"$PIDFILE"
exec sleep 60
EOF
chmod +x slow.sh
for sig in TERM HUP USR1 USR2 ALRM; do
    rm -rf "sig$sig" && mkdir "sig$sig"
    export PIDFILE=$TMP/sig$sig.pid
    rm -f "$PIDFILE"
    "$EXP/run_point.sh" "sig$sig/p.json" -- ./slow.sh keep.nff </dev/null >/dev/null 2>"sig$sig.err" &
    rp=$!
    for _ in $(seq 200); do [ -s "$PIDFILE" ] && break; sleep 0.1; done
    check "run_point $sig: the command started" [ -s "$PIDFILE" ]
    kill -s "$sig" "$rp"
    wait "$rp"
    rc=$?
    code=$((128 + $(kill -l "$sig")))
    check "run_point $sig: exit $rc, expected $code" [ "$rc" -eq "$code" ]
    check "run_point $sig: says so: $(head -c 300 "sig$sig.err")" grep -qx "run_point: stopped by SIG$sig" "sig$sig.err"
    child=$(cat "$PIDFILE" 2>/dev/null)
    alive=0
    if [ -n "$child" ]; then
        for _ in $(seq 50); do kill -0 "$child" 2>/dev/null || break; sleep 0.1; done
        if kill -0 "$child" 2>/dev/null; then alive=1; kill "$child"; fi
    fi
    check "run_point $sig: its command still runs" [ "$alive" -eq 0 ]
    check "run_point $sig: files left: $(ls -A "sig$sig" | tr '\n' ' ')" [ -z "$(ls -A "sig$sig")" ]
done
finish
