#!/usr/bin/env bash
# python_empty_values.sh - an empty value is never "the default" in the tools of experiments/:
# every option or argument of `experiments/report` (each subcommand) and of the study scripts
# that takes a value refuses '' (exit 2, the option named) before anything is written, so that
# `--doc ''` cannot rewrite docs/*.md or docs/img/ of the source tree; an option missing its
# value is refused the same way (no "unbound variable"), and so is an option given twice (the
# executables' `given 2 times; give it once`); and a study's --build folder without
# the executables is refused before any point runs. The tools run from a copy of experiments/ in
# a scratch tree, so that a tool that took '' as its default writes into that copy's docs/, not
# into the source tree.
#
# Usage (CTest runs it so): bash tests/hostile/python_empty_values.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
for tool in python3 jq; do
    command -v "$tool" >/dev/null || { echo "$TEST_NAME: $tool is not installed; skipped"; exit 77; }
done
time_limit 60
tree=$TMP/tree
mkdir -p "$tree/docs/img" "$tree/scenes" && cp -r "$SRC/experiments" "$tree/" || exit 1
cp "$SRC"/scenes/paper-image*.nff "$tree/scenes/" || exit 1
EXP=$tree/experiments
export TORUSRT_BUILD=$BUILD
logs=$TMP/logs
mkdir "$logs" "$TMP/work" && cd "$TMP/work" || exit 1
mkdir res empty

# refused NAME PATTERN COMMAND...: exit 2, stderr matching PATTERN, no traceback, and nothing
# new in the scratch tree's docs/ nor in the current folder.
refused() {
    local name=$1 pattern=$2 f=$logs/${1//[\/ \']/_}
    shift 2
    local before
    before=$(find "$tree/docs" . | sort)
    "${run_limited[@]}" "$@" >"$f.out" 2>"$f.err" </dev/null
    local rc=$?
    check "$name: exit $rc, expected 2: $(head -c 300 "$f.err")" [ "$rc" -eq 2 ]
    check "$name: the message names it ('$pattern'): $(head -c 300 "$f.err")" grep -q -e "$pattern" "$f.err"
    check "$name: no traceback, no unbound variable" test "$(grep -c 'Traceback\|unbound' "$f.err")" -eq 0
    check "$name: wrote $(comm -13 <(echo "$before") <(find "$tree/docs" . | sort) | tr '\n' ' ')" \
        test "$before" = "$(find "$tree/docs" . | sort)"
}
report=(python3 "$EXP/report")

# ---- experiments/report: each subcommand's options and arguments ------------------------------
refused "report reproduction --doc ''" "--doc: an empty value" "${report[@]}" reproduction res --doc ''
refused "report reproduction ''" "results: an empty value" "${report[@]}" reproduction ''
refused "report error-vs-runtime --doc ''" "--doc: an empty value" "${report[@]}" error-vs-runtime --doc ''
refused "report error-vs-runtime --img-dir ''" "--img-dir: an empty value" "${report[@]}" error-vs-runtime \
    --doc d.md --img-dir ''
refused "report error-vs-runtime --quantum ''" "--quantum: an empty value" "${report[@]}" error-vs-runtime \
    --doc d.md --img-dir img --quantum ''
refused "report error-vs-runtime --pruning ''" "--pruning: an empty value" "${report[@]}" error-vs-runtime \
    --doc d.md --img-dir img --pruning ''
refused "report error-vs-runtime --command ''" "--command: an empty value" "${report[@]}" error-vs-runtime \
    --doc d.md --img-dir img --command ''
refused "report collect ''" "results: an empty value" "${report[@]}" collect ''
refused "report plots ''" "results: an empty value" "${report[@]}" plots ''
refused "report fidelity page '' ''" "an empty value" "${report[@]}" fidelity page res ''
refused "report fidelity machines --sim ''" "an empty value" "${report[@]}" fidelity machines res out --sim ''
refused "report sweep-collect --y ''" "--y: an empty value" "${report[@]}" sweep-collect --out res --y ''

# ---- the study scripts ----------------------------------------------------------------------
# (--build naming a missing folder first: a script that took '' as the default stops there.)
nb=(--build "$TMP/work/missing")
refused "error_vs_runtime --doc ''" "--doc: an empty value" bash "$EXP/error_vs_runtime/study.sh" "${nb[@]}" --quick --doc ''
refused "error_vs_runtime --img-dir ''" "--img-dir: an empty value" bash "$EXP/error_vs_runtime/study.sh" "${nb[@]}" --quick \
    --img-dir ''
refused "error_vs_runtime --results ''" "--results: an empty value" bash "$EXP/error_vs_runtime/study.sh" "${nb[@]}" --quick \
    --results ''
refused "error_vs_runtime --build (no value)" "--build needs a value" bash "$EXP/error_vs_runtime/study.sh" "${nb[@]}" --quick \
    --build
refused "error_vs_runtime --only (no value)" "--only needs a value" bash "$EXP/error_vs_runtime/study.sh" --only
refused "quantum.sh --quanta ''" "--quanta: an empty value" bash "$EXP/error_vs_runtime/quantum.sh" "${nb[@]}" --quanta ''
refused "pruning.sh --out ''" "--out: an empty value" bash "$EXP/error_vs_runtime/pruning.sh" "${nb[@]}" --out ''
refused "sweep.sh --doc ''" "--doc: an empty value" bash "$EXP/sweep.sh" "${nb[@]}" --quick --doc ''
refused "sweep.sh --results ''" "--results: an empty value" bash "$EXP/sweep.sh" "${nb[@]}" --quick --results ''
refused "points.sh --reading ''" "--reading: an empty value" bash "$EXP/points.sh" "${nb[@]}" --reading ''
refused "points.sh RESULTS_DIR ''" "RESULTS_DIR: an empty value" bash "$EXP/points.sh" --build "$BUILD" quick ''
echo "a file" >notafolder
refused "points.sh RESULTS_DIR a file" "RESULTS_DIR 'notafolder': is a file, not a folder" \
    bash "$EXP/points.sh" --build "$BUILD" quick notafolder
for study in animation calibration mapping motion scaling; do
    refused "$study --build ''" "--build: an empty value" bash "$EXP/$study/study.sh" --build ''
done
refused "scaling --backend ''" "--backend: an empty value" bash "$EXP/scaling/study.sh" "${nb[@]}" --backend ''
refused "mapping --per-task=" "--per-task: an empty value" bash "$EXP/mapping/study.sh" "${nb[@]}" --per-task=

# ---- an option given twice: refused, as the executables refuse it (the last does not win) -----
refused "report sweep-collect --out twice" "--out: given 2 times; give it once" "${report[@]}" sweep-collect \
    --out res --out res2 --y image_time_s
refused "report error-vs-runtime --doc twice" "--doc: given 2 times; give it once" "${report[@]}" error-vs-runtime \
    --doc d.md --doc e.md --img-dir img
refused "compare-mappings --out twice" "--out: given 2 times; give it once" python3 "$EXP/compare-mappings" \
    "$tree/scenes/paper-image1.nff" --out a.png --out b.png
refused "sweep.sh --results twice" "--results: given 2 times; give it once" bash "$EXP/sweep.sh" "${nb[@]}" --quick \
    --results r1 --results r2
refused "sweep.sh --backend and --backend=" "--backend: given 2 times; give it once" bash "$EXP/sweep.sh" "${nb[@]}" \
    --quick --backend local --backend=local
refused "sweep --out twice" "--out: given 2 times; give it once" bash "$EXP/sweep" "$tree/scenes/paper-image1.nff" \
    --axis queue=0 --out o1 --out=o2
refused "sweep -j1 -j 1" "-j: given 2 times; give it once" bash "$EXP/sweep" "$tree/scenes/paper-image1.nff" \
    --axis queue=0 -j1 -j 1
refused "sweep.sh --per-task 0x2" "--per-task must be a whole number" bash "$EXP/sweep.sh" "${nb[@]}" --quick \
    --results r4 --per-task 0x2
check "sweep.sh --per-task 0x2: no results folder" [ ! -e r4 ]
printf '%s\ttrue\n' "$PWD/d1" >l1.list
for j in 010 ' 2' "$(printf '\xd9\xa3')"; do
    refused "backend -j '$j'" "must be a whole number, 1 or more" python3 "$EXP/backend" run --state st -j "$j" l1.list
done
cp "$tree/scenes/paper-image1.nff" own.nff
refused "quantum.sh --out its scene" "--out 'own.nff': is the scene file own.nff, an input" \
    bash "$EXP/error_vs_runtime/quantum.sh" "${nb[@]}" --scenes own.nff --out own.nff
refused "pruning.sh --out its scene" "--out 'own.nff': is the scene file own.nff, an input" \
    bash "$EXP/error_vs_runtime/pruning.sh" "${nb[@]}" --scenes own.nff --out own.nff
check "quantum.sh and pruning.sh --out their scene: the scene kept" cmp -s own.nff "$tree/scenes/paper-image1.nff"
for m in 010 .5 inf; do
    refused "quantum.sh --max-error $m" "--max-error: a percentage" bash "$EXP/error_vs_runtime/quantum.sh" "${nb[@]}" \
        --max-error "$m"
done
refused "quantum.sh --quanta twice" "--quanta: given 2 times; give it once" bash "$EXP/error_vs_runtime/quantum.sh" \
    "${nb[@]}" --quanta 1 --quanta 2
refused "scaling --build twice" "--build: given 2 times; give it once" bash "$EXP/scaling/study.sh" "${nb[@]}" "${nb[@]}"

# ---- a --build folder without the executables: refused before any point runs ----------------
refused "buffers --build (no executables)" "has no torusrt-sim" bash "$EXP/buffers/study.sh" --quick \
    --build "$TMP/work/empty" --results bq
check "buffers --build (no executables): no results folder" [ ! -e bq ]
refused "scaling --build (no executables)" "has no torusrt-sim" bash "$EXP/scaling/study.sh" --build \
    "$TMP/work/empty"
refused "error study --build (no executables)" "has no torusrt-sim" bash "$EXP/error_vs_runtime/study.sh" --quick \
    --build "$TMP/work/empty"
finish
