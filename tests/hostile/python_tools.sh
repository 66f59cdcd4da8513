#!/usr/bin/env bash
# python_tools.sh - the Python tools of experiments/ under the executables' output rules
# (experiments/output_files.py): compare-mappings, sweep, run_point.sh, the backend, report and
# the studies' job counts. An output naming an input (also by another spelling), two outputs on one file,
# a FIFO or a folder as an output: refused (exit 2, the option named), the input unchanged. An
# output that is a link: its target written, the link kept. A point JSON that is not a report
# (garbage, an array, {}): named and run again. A sweep into the same --out with another scene
# or other options: every point run again, the CSV the same as a fresh sweep's. -j 0 and -j abc
# refused; -j 99999 capped at the number of points.
#
# Usage (CTest runs it so): bash tests/hostile/python_tools.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
for tool in python3 parallel gnuplot; do
    command -v "$tool" >/dev/null || { echo "$TEST_NAME: $tool is not installed; skipped"; exit 77; }
done
time_limit 100
EXP=$SRC/experiments
export TORUSRT_BUILD=$BUILD
scene1=$(source_scene paper-image1) || exit 1
scene2=$(source_scene paper-image2) || exit 1
cd "$TMP" || exit 1
cp "$scene1" s1.nff
cp "$scene2" s2.nff
cp "$SRC/timing/literal.timing" t.timing
small=(--size 8x8)

# refused NAME PATTERN COMMAND...: exit 2, stderr matching PATTERN (the option and the file).
refused() {
    local name=$1 pattern=$2
    shift 2
    "${run_limited[@]}" "$@" >"$name.out" 2>"$name.err" </dev/null
    local rc=$?
    check "$name: exit $rc, expected 2: $(head -c 300 "$name.err")" [ "$rc" -eq 2 ]
    check "$name: the message names it ('$pattern'): $(head -c 300 "$name.err")" grep -q -e "$pattern" "$name.err"
}
# same NAME FILE KEPT: FILE still holds KEPT's bytes (and is put back, for the next case).
same() {
    check "$1: $2 changed" cmp -s "$2" "$3"
    rm -f "$2" && cp "$3" "$2"
}
# rows CSV: the CSV without its wall-clock columns.
rows() { nowall "$1"; }

# ---- compare-mappings ----------------------------------------------------------------------
cm=("$EXP/compare-mappings" --build "$BUILD" --map "block,cyclic")
cmopt=(-- --ips 2 "${small[@]}")
cp s1.nff keep.nff && cp t.timing keep.timing
refused "cm --out the scene" "--out 's1.nff': is the scene file" "${cm[@]}" s1.nff --out s1.nff "${cmopt[@]}"
same "cm --out the scene" s1.nff keep.nff
mkdir sub
refused "cm --out the scene by another spelling" "an input" "${cm[@]}" s1.nff --out sub/../s1.nff "${cmopt[@]}"
same "cm --out sub/../s1.nff" s1.nff keep.nff
refused "cm --out the --timing file" "is the --timing file t.timing" "${cm[@]}" s1.nff --out t.timing \
    "${cmopt[@]}" --timing t.timing
same "cm --out the --timing file" t.timing keep.timing
mkfifo fifo.png
refused "cm --out a FIFO" "--out 'fifo.png': is a FIFO" "${cm[@]}" s1.nff --out fifo.png "${cmopt[@]}"
mkdir dir.png
refused "cm --out a folder" "--out 'dir.png': is a folder" "${cm[@]}" s1.nff --out dir.png "${cmopt[@]}"
refused "cm --out in no folder" "folder 'nowhere' does not exist" "${cm[@]}" s1.nff --out nowhere/m.png "${cmopt[@]}"
ln -s sub/plot.png link.png
"${run_limited[@]}" "${cm[@]}" s1.nff --out link.png "${cmopt[@]}" >cm-link.out 2>cm-link.err </dev/null
check "cm --out a link: exit $?: $(head -c 300 cm-link.err)" [ -s sub/plot.png ]
check "cm --out a link: a PNG" grep -q PNG <(head -c 8 sub/plot.png)
check "cm --out a link: the link is kept" [ -L link.png ]
left=(sub/.[!.]* sub/*)
check "cm: no temporary left: ${left[*]}" [ "${left[*]}" = "sub/.[!.]* sub/plot.png" ]

# ---- sweep ---------------------------------------------------------------------------------
sweep=("$EXP/sweep" --build "$BUILD")
# swept NAME SCENE OUT ARGS...: a sweep over ips=1,2 that must succeed.
swept() {
    local name=$1 scene=$2 out=$3
    shift 3
    "${run_limited[@]}" "${sweep[@]}" "$scene" --axis ips=1,2 --out "$out" "$@" >"$name.out" 2>"$name.err" </dev/null
    local rc=$?
    check "$name: exit $rc: $(tail -c 300 "$name.err")" [ "$rc" -eq 0 ]
    return $rc
}
swept "sweep fresh s2" s2.nff fresh2 -- "${small[@]}"
swept "sweep fresh s1 at 8x12" s1.nff fresh1 -- --size 8x12

mkdir o1
cp s1.nff o1/sweep.png && cp s1.nff keep.nff
refused "sweep: the scene is the plot" "--out '.*o1/sweep.png': is the scene file" \
    "${sweep[@]}" o1/sweep.png --axis ips=1,2 --out o1 -- "${small[@]}"
same "sweep: the scene is the plot" o1/sweep.png keep.nff
rm o1/sweep.png
printf 'name\tips\n' >o1/points.tsv && cp o1/points.tsv keep.tsv
refused "sweep: --timing is the point table" "is the --timing file .*points.tsv, an input" \
    "${sweep[@]}" s1.nff --axis ips=1,2 --out o1 -- "${small[@]}" --timing o1/points.tsv
same "sweep: --timing is the point table" o1/points.tsv keep.tsv
ln -s points.tsv o1/sweep.csv
refused "sweep: the CSV is the point table" "sweep.csv': is also the file of --out '.*points.tsv'" \
    "${sweep[@]}" s1.nff --axis ips=1,2 --out o1 -- "${small[@]}"
same "sweep: the CSV is the point table" o1/points.tsv keep.tsv
rm o1/sweep.csv && mkfifo o1/sweep.csv
refused "sweep: the CSV a FIFO" "sweep.csv': is a FIFO" "${sweep[@]}" s1.nff --axis ips=1,2 --out o1 -- "${small[@]}"
rm o1/sweep.csv && mkdir o1/sweep.csv
refused "sweep: the CSV a folder" "sweep.csv': is a folder" "${sweep[@]}" s1.nff --axis ips=1,2 --out o1 -- "${small[@]}"
rmdir o1/sweep.csv
check "sweep: no point ran while refused" [ -z "$(ls -A o1/points 2>/dev/null)" ]
ln -s ../o1-csv o1/sweep.csv
if swept "sweep: the CSV a link" s2.nff o1 -- "${small[@]}"; then
    check "sweep: the CSV a link: the link is kept" [ -L o1/sweep.csv ]
    check "sweep: the CSV a link: its target holds the CSV" cmp -s <(rows o1-csv) <(rows fresh2/sweep.csv)
fi

# The same --out with another scene, then other options: every point again, the fresh figures.
if swept "sweep: s1 into s2's --out" s1.nff fresh2 -- "${small[@]}"; then
    check "sweep: s1 into s2's --out: no point kept ($(grep -c 'done before' 'sweep: s1 into s2'"'"'s --out.out'))" \
        grep -q "(0 done before)" "sweep: s1 into s2's --out.out"
    swept "sweep: s1 again" s1.nff fresh1x -- "${small[@]}" &&
        check "sweep: s1 into s2's --out: the CSV is s1's" cmp -s <(rows fresh2/sweep.csv) <(rows fresh1x/sweep.csv)
fi
if swept "sweep: other options into the same --out" s1.nff fresh2 -- --size 8x12; then
    check "sweep: other options: the CSV is the fresh one's" cmp -s <(rows fresh2/sweep.csv) <(rows fresh1/sweep.csv)
fi
swept "sweep: the same again" s1.nff fresh2 -- --size 8x12 &&
    check "sweep: the same command again keeps both points" grep -q "(2 done before)" "sweep: the same again.out"

# A point JSON that is not a report: named, run again.
for bad in garbage array empty; do
    case $bad in garbage) text='not json at all' ;; array) text='[1, 2]' ;; empty) text='{}' ;; esac
    printf '%s\n' "$text" >fresh1/points/ips_2.json
    if swept "sweep: a $bad point JSON" s1.nff fresh1 -- --size 8x12; then
        check "sweep: a $bad point JSON is named: $(head -c 300 "sweep: a $bad point JSON.err")" \
            grep -q "points/ips_2.json: not a JSON report" "sweep: a $bad point JSON.err"
        check "sweep: a $bad point JSON runs again" grep -q "(1 done before)" "sweep: a $bad point JSON.out"
        check "sweep: a $bad point JSON: the CSV is whole" cmp -s <(rows fresh1/sweep.csv) <(rows fresh2/sweep.csv)
    fi
done

# -j
refused "sweep -j 0" "-j must be a whole number" "${sweep[@]}" s1.nff --axis ips=1,2 --out j0 -j 0 -- "${small[@]}"
refused "sweep -j abc" "-j must be a whole number" "${sweep[@]}" s1.nff --axis ips=1,2 --out jabc -j abc -- "${small[@]}"
check "sweep -j 0: nothing ran" [ ! -e j0/points.list ]
swept "sweep -j 99999" s1.nff j99999 -j 99999 -- "${small[@]}" &&
    check "sweep -j 99999: capped at the 2 points: $(grep -o '(-j [0-9]*)' 'sweep -j 99999.out')" \
        grep -q "to run on this machine (-j 2)" "sweep -j 99999.out"

# ---- the backend ---------------------------------------------------------------------------
mkdir be
printf '%s\t%s\n' "$TMP/be/a.json" "echo {} >$TMP/be/a.json" "$TMP/be/b.json" "echo {} >$TMP/be/b.json" >be/list
backend=(python3 "$EXP/backend" run --state be/state)
refused "backend -j 0" "-j/--jobs: must be a whole number" "${backend[@]}" -j 0 be/list
refused "backend --per-task 0" "--per-task: must be a whole number" "${backend[@]}" --per-task 0 be/list
refused "backend --state ''" "--state: an empty value" python3 "$EXP/backend" run --state '' be/list
for name in "backend -j 0" "backend --per-task 0" "backend --state ''"; do
    check "$name: one line, not the usage: $(head -c 300 "$name.err")" [ "$(wc -l <"$name.err")" -eq 1 ]
done
refused "backend -j abc" "-j/--jobs: must be a whole number" "${backend[@]}" -j abc be/list
mkfifo be/runs.tsv
refused "backend --runs a FIFO" "--runs 'be/runs.tsv': is a FIFO" "${backend[@]}" --runs be/runs.tsv be/list
check "backend: refused, nothing ran" [ ! -e be/a.json ]
"${run_limited[@]}" "${backend[@]}" -j 99999 be/list >be.out 2>be.err </dev/null
check "backend -j 99999: exit $?, both points run" test -s be/a.json -a -s be/b.json
check "backend -j 99999: capped at 2" grep -q "(-j 2)" be.out

# ---- run_point.sh (the reproduction's points) ------------------------------------------------
mkdir rp
mkfifo rp/a.json
refused "run_point: the JSON a FIFO" "rp/a.json: not a regular file" \
    "$EXP/run_point.sh" rp/a.json -- "$BUILD/torusrt-sim" s1.nff "${small[@]}" --t1 1
mkdir rp/b.png
refused "run_point: the PNG a folder" "rp/b.png: not a regular file" \
    "$EXP/run_point.sh" rp/b.json -- "$BUILD/torusrt-sim" s1.nff "${small[@]}" --t1 1
ln -s c-real.json rp/c.json
"${run_limited[@]}" "$EXP/run_point.sh" rp/c.json -- "$BUILD/torusrt-sim" s1.nff "${small[@]}" --t1 1 \
    >rp.out 2>rp.err </dev/null
check "run_point: the JSON a link: exit $?, the link kept" [ -L rp/c.json ]
check "run_point: the JSON a link: its file written" [ -s rp/c-real.json ]

# ---- report --------------------------------------------------------------------------------
report=(python3 "$EXP/report")
printf 'a,b\n' >q.csv && cp q.csv p.csv && cp q.csv keep.csv
refused "report --doc the --quantum file" "--doc 'q.csv': is the --quantum file q.csv, an input" \
    "${report[@]}" error-vs-runtime --quantum q.csv --pruning p.csv --doc q.csv --img-dir sub
same "report --doc the --quantum file" q.csv keep.csv
refused "report --doc a FIFO" "--doc 'fifo.png': is a FIFO" \
    "${report[@]}" error-vs-runtime --quantum q.csv --pruning p.csv --doc fifo.png --img-dir sub
refused "report --doc a folder" "--doc 'dir.png': is a folder" \
    "${report[@]}" error-vs-runtime --quantum q.csv --pruning p.csv --doc dir.png --img-dir sub
ln -s ../q.csv sub/error-pruning.png
refused "report: a picture is an input through a link" "error-pruning.png': is the --quantum file" \
    "${report[@]}" error-vs-runtime --quantum q.csv --pruning p.csv --doc d.md --img-dir sub
same "report: a picture is an input through a link" q.csv keep.csv
# sweep-collect: the CSV through a link, a point JSON gone bad after its run named.
rm -f fresh1/sweep.csv && ln -s ../collect.csv fresh1/sweep.csv
"${run_limited[@]}" "${report[@]}" sweep-collect --out fresh1 >collect.out 2>collect.err </dev/null
check "report sweep-collect: the CSV a link: exit $?, link kept" [ -L fresh1/sweep.csv ]
check "report sweep-collect: the CSV a link: its file written" [ -s collect.csv ]
printf '[]\n' >fresh1/points/ips_1.json
"${run_limited[@]}" "${report[@]}" sweep-collect --out fresh1 >collect.out 2>collect.err </dev/null
rc=$?
check "report sweep-collect: an array point JSON fails the point: exit $rc" [ "$rc" -eq 1 ]
check "report sweep-collect: an array point JSON is named: $(head -c 300 collect.err)" \
    grep -q "points/ips_1.json: not a JSON report (a list" collect.err
check "report sweep-collect: no traceback" test "$(grep -c Traceback collect.err)" -eq 0

# ---- the studies' job counts -----------------------------------------------------------------
# A copy of experiments/, so that a study that wrongly started writes into $TMP, not the tree.
cp -r "$EXP" copy
refused "study JOBS 0" "JOBS must be a whole number" bash copy/mapping/study.sh "$BUILD" 0
refused "study -j abc" "-j must be a whole number" bash copy/mapping/study.sh --build "$BUILD" -j abc
refused "all_scenes -j 0" "-j must be a whole number" bash copy/buffers/all_scenes.sh -j 0 "$BUILD"
refused "all_scenes -j abc" "-j must be a whole number" bash copy/buffers/all_scenes.sh -j abc "$BUILD"

finish
