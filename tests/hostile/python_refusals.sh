#!/usr/bin/env bash
# python_refusals.sh - the Python and shell tools of experiments/ never end in a traceback: a
# command line that would make every run fail is refused before anything runs or is made
# (exit 2, the option named), a failed write names the file and the reason (exit 1):
# - after `--` (compare-mappings, a sweep's fixed options, run_point.sh's command): --help, -h,
#   --version, --dump-config, -o glued to its file (-ox.png, -qox.png) and --stats=FILE; for the
#   sweep and compare-mappings an animation (--frames, --orbit, --motion), and --stats-interval
#   for compare-mappings (its series would be dropped);
# - standard output on a full device, a closed pipe or closed: `standard output: cannot write:
#   REASON`, exit 1 (compare-mappings, report, the backend, the sweep, a study's --help, and the
#   --help of compare-mappings, report and the backend);
# - an empty value (--out '', --state '', --runs '', --columns '', a report's folder or file):
#   exit 2, nothing written into the current folder;
# - the sweep's --out naming the scene or a file, the backend's --state naming a file, a study's
#   --results naming a file: exit 2 naming it; a refused sweep leaves no --out folder;
# - compare-mappings' --map: an empty or repeated mapping refused, as the sweep's axis values;
# - report machine: a report whose config is null, and an explicit --build without torusrt-sim;
# - report compare: a row with more fields than its header, a header naming a column twice;
# - run_point.sh: no command after --, an empty OUT.json, a --t1-from whose sim_time_s is not a
#   number above 0 (1e-400 included), --t1 given with --t1-from;
# - the sweep's per-point temporaries are unique per process (two sweeps into one --out);
# - the sweep: a point whose name passes what its files' names may hold, and a TMPDIR that is no
#   folder one can write into, refused naming them (exit 2) before anything is made.
#
# Usage (CTest runs it so): bash tests/hostile/python_refusals.sh BUILD_DIR SOURCE_DIR
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

# exits STATUS NAME PATTERN COMMAND...: exit STATUS, stderr matching PATTERN, no traceback; the
# command's output in $logs/NAME.out and NAME.err (a space, ' or / of NAME as _).
logs=$TMP/logs
mkdir "$logs" && mkdir work && cd work || exit 1
cp "$scene1" s1.nff && cp s1.nff keep.nff
exits() {
    local status=$1 name=$2 pattern=$3 f=$logs/${2//[\/ \']/_}
    shift 3
    "${run_limited[@]}" "$@" >"$f.out" 2>"$f.err" </dev/null
    local rc=$?
    check "$name: exit $rc, expected $status: $(head -c 300 "$f.err")" [ "$rc" -eq "$status" ]
    check "$name: the message names it ('$pattern'): $(head -c 300 "$f.err")" grep -q -e "$pattern" "$f.err"
    check "$name: no traceback" test "$(grep -c Traceback "$f.err")" -eq 0
}
refused() { exits 2 "$@"; }
# full STATUS NAME PATTERN COMMAND...: as exits, with standard output on /dev/full (and no
# errno number in the message).
full() {
    local status=$1 name=$2 pattern=$3 f=$logs/${2//[\/ \']/_}
    shift 3
    "${run_limited[@]}" "$@" >/dev/full 2>"$f.err" </dev/null
    local rc=$?
    check "$name: exit $rc, expected $status: $(head -c 300 "$f.err")" [ "$rc" -eq "$status" ]
    check "$name: the message names it ('$pattern'): $(head -c 300 "$f.err")" grep -q -e "$pattern" "$f.err"
    check "$name: no traceback, no errno number" test "$(grep -c 'Traceback\|Errno' "$f.err")" -eq 0
}
# nothing_new NAME: the current folder holds what it held at the last snapshot.
snapshot() { ls -A >snap.list; }
nothing_new() { check "$1: wrote into the current folder: $(ls -A | comm -13 snap.list - | tr '\n' ' ')" \
    cmp -s snap.list <(ls -A); }
ENOSPC="standard output: cannot write: No space left on device"
cm=("$EXP/compare-mappings" --build "$BUILD" --map "block,cyclic")
sweep=("$EXP/sweep" --build "$BUILD")
rp=("$EXP/run_point.sh" rp/p.json)
"${run_limited[@]}" "$BUILD/torusrt-sim" s1.nff -q -o a.png "${small[@]}" --stats a.json </dev/null
check "a report to read: exit $?" [ -s a.json ]
printf '/dev/null\ttrue\n' >list.tsv  # a point list

# ---- options that make every run fail, after -- ------------------------------------
for opt in --help -h --version --dump-config "--frames 2 --orbit 3" --stats-interval=0.1; do
    read -r -a words <<<"$opt"
    snapshot
    refused "cm -- $opt" "${words[0]%%=*} after --" "${cm[@]}" s1.nff --out c.png -- --ips 2 "${small[@]}" "${words[@]}"
    nothing_new "cm -- $opt"
done
printf 'torusrt-motion 1\nframes 2\n' >m.motion
for opt in --help --version --dump-config "--frames 2 --orbit 3" "--motion m.motion"; do
    read -r -a words <<<"$opt"
    refused "sweep -- $opt" "${words[0]} among the fixed options" "${sweep[@]}" s1.nff --axis ips=1,2 --out sw -- \
        "${small[@]}" "${words[@]}"
    check "sweep -- $opt: no --out folder made" [ ! -e sw ]
done
refused "sweep -- -qh" "-h among the fixed options" "${sweep[@]}" s1.nff --axis ips=1,2 --out sw -- -qh
check "sweep -- -qh: no --out folder made" [ ! -e sw ]
refused "sweep --axis frames" "--axis 'frames=1,2'" "${sweep[@]}" s1.nff --axis frames=1,2 --out sw -- "${small[@]}"
check "sweep --axis frames: no --out folder made" [ ! -e sw ]

# ---- -o glued to its file, --stats=FILE ---------------------------------------------------
refused "cm -- -ox.png" "-o after --" "${cm[@]}" s1.nff --out c.png -- --ips 2 "${small[@]}" -ox.png
refused "cm -- -qox.png" "-o after --" "${cm[@]}" s1.nff --out c.png -- --ips 2 "${small[@]}" -qox.png
refused "sweep -- -ox.png" "-o among the fixed options" "${sweep[@]}" s1.nff --axis ips=1,2 --out sw -- -ox.png
refused "sweep -- --stats=x.json" "--stats among the fixed options" "${sweep[@]}" s1.nff --axis ips=1,2 --out sw \
    -- --stats=x.json
check "sweep -- -ox.png: no --out folder made" [ ! -e sw ]
# A point whose files' names would pass 255 bytes, and a TMPDIR GNU parallel cannot use: named
# before anything runs or is made, never a point failing with an empty reason.
mkdir -p cx && printf '[network]\nqueue="1"\n' >"cx/$(printf 'm%.0s' $(seq 240)).toml"
refused "sweep, a point name of 255 bytes" "the point config_cx_m.*: its name is 255 bytes" \
    "${sweep[@]}" s1.nff --axis "config=$(echo cx/*.toml)" --out sw -- "${small[@]}"
refused "sweep, TMPDIR missing" "TMPDIR '$TMP/nonexistent': not a folder" \
    env TMPDIR="$TMP/nonexistent" "${sweep[@]}" s1.nff --axis ips=1 --out sw -- "${small[@]}"
check "sweep, long name or TMPDIR: no --out folder made" [ ! -e sw ]
# A list value with blanks around it, a bad --columns of report compare: a refused command line.
refused "cm --map 'block, cyclic'" "' cyclic' has blanks around it" "$EXP/compare-mappings" s1.nff \
    --map 'block, cyclic' --build "$BUILD" -- --ips 2 "${small[@]}"
refused "report compare --columns ',,'" "--columns ',,': an empty value" python3 "$EXP/report" compare . . \
    --columns ',,'
refused "cm -- --cells 4 --cells 5" "the options after -- do not check out (no run was made): .*--cells: given 2" \
    "$EXP/compare-mappings" s1.nff --out cc.png --build "$BUILD" -- --ips 2 "${small[@]}" --cells 4 --cells 5
check "cm -- --cells 4 --cells 5: no --out" [ ! -e cc.png ]
# Started as a package from the source tree: its help, not a missing module called memory.
(cd "$SRC" && python3 -m experiments.backend --help >"$logs/m.out" 2>"$logs/m.err")
check "python3 -m experiments.backend --help: exit $?: $(head -c 200 "$logs/m.err")" grep -q "^usage:" "$logs/m.out"
# An --out that cannot be made: under a file, or a link that loops: a refused command line (2).
ln -sfn loopA loopB && ln -sfn loopB loopA
refused "sweep --out under a file" "--out 's1.nff/sub': cannot be made: '.*s1.nff' is a file" \
    "${sweep[@]}" s1.nff --axis ips=1 --out s1.nff/sub -- "${small[@]}"
refused "sweep --out a link loop" "--out 'loopA': '.*loopA' is a link that names no folder" \
    "${sweep[@]}" s1.nff --axis ips=1 --out loopA -- "${small[@]}"
rm -f loopA loopB
mkfifo jf.nff
refused "sweep, a scene that is a FIFO" "scene 'jf.nff': is a FIFO, not a regular file" \
    "${sweep[@]}" jf.nff --axis ips=1 --out sw -- "${small[@]}"
rm -f jf.nff
refused "run_point -ox.png" "'-o'\|-o 'x.png'" "${rp[@]}" -- "$BUILD/torusrt-sim" s1.nff "${small[@]}" -ox.png
refused "run_point --stats=x.json" "--stats" "${rp[@]}" -- "$BUILD/torusrt-sim" s1.nff "${small[@]}" --stats=x.json
refused "run_point --help" "--help in the command" "${rp[@]}" -- "$BUILD/torusrt-sim" s1.nff --help
refused "run_point --dump-config" "--dump-config in the command" "${rp[@]}" -- "$BUILD/torusrt-sim" s1.nff --dump-config
check "run_point refusals: nothing written" [ ! -e rp/p.json ] && [ ! -e rp/p.log ]

# ---- standard output on a full device, or a closed pipe --------------------------
full 1 "cm >/dev/full" "compare-mappings: $ENOSPC" "${cm[@]}" s1.nff --out c.png -- --ips 2 "${small[@]}"
full 1 "report machine >/dev/full" "report: $ENOSPC" python3 "$EXP/report" machine a.json
full 1 "sweep >/dev/full" "$ENOSPC" "${sweep[@]}" s1.nff --axis ips=1,2 --out swfull -- "${small[@]}"
full 1 "fidelity --help >/dev/full" "study.sh: $ENOSPC" bash "$EXP/fidelity/study.sh" --help
full 1 "sweep --help >/dev/full" "sweep: $ENOSPC" "${sweep[@]}" --help
full 1 "cm --help >/dev/full" "compare-mappings: $ENOSPC" "$EXP/compare-mappings" --help
full 1 "report --help >/dev/full" "experiments/report: $ENOSPC" python3 "$EXP/report" --help
full 1 "report machine --help >/dev/full" "experiments/report: $ENOSPC" python3 "$EXP/report" machine --help
full 1 "backend run --help >/dev/full" "experiments/backend: $ENOSPC" python3 "$EXP/backend" run --help
# --help with standard output closed: named, never printed on standard error instead.
python3 "$EXP/report" machine --help >&- 2>help-closed.err
rc=$?
check "report machine --help >&-: exit $rc, expected 1" [ "$rc" -eq 1 ]
check "report machine --help >&-: $(head -c 300 help-closed.err)" \
    grep -qx "experiments/report: standard output: cannot write: Bad file descriptor" help-closed.err
# A closed pipe: its reading end is closed before the sweep starts.
closed_pipe() {
    python3 -c 'import os, subprocess, sys
r, w = os.pipe()
os.close(r)
sys.exit(subprocess.call(sys.argv[1:], stdout=w))' "$@"
}
closed_pipe "${run_limited[@]}" "${sweep[@]}" s1.nff --axis ips=1,2 --out swpipe -- "${small[@]}" 2>pipe.err </dev/null
rc=$?
check "sweep | closed: exit $rc, expected 1: $(head -c 300 pipe.err)" [ "$rc" -eq 1 ]
check "sweep | closed: names standard output: $(head -c 300 pipe.err)" \
    grep -q "standard output: cannot write: Broken pipe" pipe.err
check "sweep | closed: no errno number, no traceback" test "$(grep -c 'Errno\|Traceback' pipe.err)" -eq 0

# ---- empty values ------------------------------------------------------------------------
snapshot
refused "sweep --out ''" "--out needs a value" "${sweep[@]}" s1.nff --axis ips=1 --out '' -- "${small[@]}"
refused "sweep --columns ''" "--columns needs a value" "${sweep[@]}" s1.nff --axis ips=1 --columns '' -- "${small[@]}"
refused "backend --state ''" "--state: an empty value" python3 "$EXP/backend" run --state '' list.tsv
refused "backend --runs ''" "--runs: an empty value" python3 "$EXP/backend" run --state st --runs '' list.tsv
refused "report compare '' DIR" "old: an empty value" python3 "$EXP/report" compare '' .
refused "report compare --columns ''" "--columns: an empty value" python3 "$EXP/report" compare . . --columns ''
refused "report machine --compare ''" "--compare: an empty value" python3 "$EXP/report" machine a.json --compare ''
refused "cm --build ''" "--build: an empty value" "$EXP/compare-mappings" s1.nff --build '' -- --ips 2
nothing_new "empty values"

# ---- report machine --build without torusrt-sim -----------------------------------------
python3 "$EXP/report" machine a.json >a.toml 2>/dev/null
mkdir nobuild
refused "report machine --build nonexist" "--build '/nonexist': no torusrt-sim" \
    python3 "$EXP/report" machine a.json --compare a.toml --build /nonexist
refused "report machine --build a folder without it" "--build 'nobuild': no torusrt-sim" \
    python3 "$EXP/report" machine a.json --compare a.toml --build nobuild

# ---- report machine on a report whose config is null --------------------------------------
python3 -c "import json; d = json.load(open('a.json')); d['config'] = None; json.dump(d, open('n.json', 'w'))"
exits 1 "report machine config null" "n.json: config: null, not an object" python3 "$EXP/report" machine n.json

# ---- --out, --state, --results naming a file; no --out left by a refused sweep ------------
refused "sweep --out the scene" "--out 's1.nff': is the scene file" "${sweep[@]}" s1.nff --axis ips=1 --out s1.nff
check "sweep --out the scene: unchanged" cmp -s s1.nff keep.nff
echo x >afile
refused "sweep --out a file" "--out 'afile': is a file, not a folder" "${sweep[@]}" s1.nff --axis ips=1 --out afile
refused "backend --state a file" "--state 'afile': is a file, not a folder" \
    python3 "$EXP/backend" run --state afile list.tsv
refused "fidelity --results a file" "--results 'afile': is a file, not a folder" \
    bash "$EXP/fidelity/study.sh" --smoke --build "$BUILD" --results afile
mkdir -p a && cp "$SRC/timing/literal.timing" a/t.timing && cp a/t.timing a_t.timing
refused "sweep two points of one name" "have one name" "${sweep[@]}" s1.nff --axis timing=a/t.timing,a_t.timing \
    --out s14 -- "${small[@]}"
check "sweep two points of one name: no --out folder made" [ ! -e s14 ]
refused "sweep a failed first-point check" "do not check out" "${sweep[@]}" s1.nff --axis ips=1 --out s15 \
    -- --no-such-option
check "sweep a failed first-point check: no --out folder made" [ ! -e s15 ]

# ---- compare-mappings' --map checked as the sweep's axis values ---------------------------
refused "cm --map block," "--map 'block,': an empty value" "${cm[@]:0:3}" --map block, s1.nff --out c.png -- --ips 2
refused "cm --map block,block" "'block' is given twice" "${cm[@]:0:3}" --map block,block s1.nff --out c.png -- --ips 2
refused "sweep --axis map=block,block" "--axis 'map=block,block': 'block' is given twice" \
    "${sweep[@]}" s1.nff --axis map=block,block --out sw

# ---- report compare on a CSV with more fields than its header, a column named twice -------
mkdir -p old new
printf 'ips,status,sim_time_s\n1,ok,2\n' >old/fig7.csv
printf 'ips,status,sim_time_s\n1,ok,2,9\n' >new/fig7.csv
exits 1 "compare a row with an extra field" "fig7.csv: line 2: 4 fields, the header has 3" \
    python3 "$EXP/report" compare old new
printf 'ips,status,sim_time_s,sim_time_s\n1,ok,3,2\n' >new/fig7.csv
exits 1 "compare a column named twice" "fig7.csv: line 1: the column 'sim_time_s' is named twice" \
    python3 "$EXP/report" compare old new

# ---- run_point.sh's command line ----------------------------------------------------------
refused "run_point no command" "no command after --" "${rp[@]}" --
check "run_point no command: no log" [ ! -e rp/p.log ]
refused "run_point ''" "not an empty value" "$EXP/run_point.sh" ''
echo '{"sim_time_s": "0.5ms"}' >t1.json
exits 3 "run_point --t1-from a string" "no sim_time_s number" "$EXP/run_point.sh" rp/p.json --t1-from t1.json \
    -- "$BUILD/torusrt-sim" s1.nff "${small[@]}"
echo '{"sim_time_s": 1e-400}' >t1.json
exits 3 "run_point --t1-from 1e-400" "no sim_time_s number above 0" "$EXP/run_point.sh" rp/p.json --t1-from t1.json \
    -- "$BUILD/torusrt-sim" s1.nff "${small[@]}"
echo '{"sim_time_s": 0.5}' >t1.json
refused "run_point --t1 and --t1-from" "give T(1) once" "$EXP/run_point.sh" rp/p.json --t1-from t1.json \
    -- "$BUILD/torusrt-sim" s1.nff "${small[@]}" --t1 0.4
check "run_point refusals: no JSON, no log" [ ! -e rp/p.json ] && [ ! -e rp/p.log ]

# ---- two sweeps into one --out: no shared temporary ---------------------------------------------
"${run_limited[@]}" "${sweep[@]}" s1.nff --axis ips=1,2 --out two -- "${small[@]}" >two.out 2>two.err </dev/null
check "sweep for the point list: exit $?" [ -s two/points.list ]
check "a point's temporaries are per process: $(grep -o 'stats [^ ]*' two/points.list | head -1)" \
    grep -q -e "ips_1.json.tmp'\\?\"\$u\"" two/points.list
check "\$u is the host and the process: $(grep -o 'u=[^;]*' two/points.list | head -1)" \
    grep -q 'u=.$(hostname -s 2>/dev/null || echo host).$$;' two/points.list
left=(two/points/*.tmp*)
check "no temporary left: ${left[*]}" [ ! -e "${left[0]}" ]

finish
