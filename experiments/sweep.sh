#!/usr/bin/env bash
# sweep.sh - the whole reproduction in one command: run every point, then collect the CSVs (experiments/report),
# draw the plots (experiments/plots/*.gp) and write the comparison with the paper (experiments/report).
#
#   experiments/sweep.sh [--quick] [--results DIR] [-j N] [--backend local|ssh:HOSTFILE|slurm]
#                        [--slurm-args "..."] [--per-task K] [--build DIR] [--doc FILE]
#                        [--no-report] [--no-clusters]
#
#   --quick              small image (32x32), few points: the CTest smoke run (seconds)
#   --results DIR        where the JSONs, CSVs, plots and logs go
#                        (default experiments/results, or experiments/results-quick)
#   -j N                 points in flight (default: one per core; over ssh per machine; on
#                        Slurm no limit)
#   --backend B          local (GNU parallel, the default), ssh:HOSTFILE (GNU parallel over the
#                        machines of an sshlogin file; ':' is this machine) or slurm (one job
#                        array per phase); the repository, build and results folder must be at
#                        the same paths on every machine (docs/cluster-runs.md)
#   --sshloginfile FILE  the same as --backend ssh:FILE
#   --slurm-args "..."   more sbatch options (partition, account, time): one, several in one
#                        quoted word, or after '=' (--slurm-args=--account=foo)
#   --per-task K         points per Slurm array task (default 4)
#   --build DIR          build folder holding torusrt-sim (default $TORUSRT_BUILD, else build/)
#   --doc FILE           the report to write (default docs/reproduction.md for the full sweep,
#                        RESULTS/reproduction.md for --quick); plots are copied beside it in img/;
#                        not in scenes/, machines/, timing/, experiments/ or RESULTS (but
#                        RESULTS/NAME.md), nor a file the run reads: exit 2
#   --no-report          run the points only
#   --no-clusters        leave out figures 10-12 (for builds without the cluster model)
#
# Every point runs under each reading (experiments/lib.sh READINGS: fitted, the default, and
# calibrated and literal); RES/READING holds that reading's JSONs, CSVs and plots, RES the point
# lists, joblogs and runs.tsv. The one-processor points (phase 1) run first, since every other point takes its T(1) from
# them. Points already done are skipped, so an interrupted or partly failed sweep is resumed by
# running the same command again. Failed points are listed with their command lines (from
# RESULTS/joblog) and the exit status is then 1; the collection step marks them in the CSVs.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

mode=full results="" build=$BUILD doc="" report=1 popt=()
while [ $# -gt 0 ]; do
    case $1 in
        --results|--sshloginfile|--build|--doc) need_value "$@" ;;
    esac
    case $1 in
        --quick) mode=quick; shift ;;
        --results) results=$2; shift 2 ;;
        --sshloginfile) BACKEND=ssh:$2; shift 2 ;;
        --build) build=$2; shift 2 ;;
        --doc) doc=$2; shift 2 ;;
        --no-report) report=0; shift ;;
        --no-clusters) popt+=(--no-clusters); shift ;;
        -h|--help) show_help '^set -uo' ;;
        *) backend_option "$@" || die "unknown argument '$1' (see --help)"; shift "$SHIFT" ;;
    esac
done
define_mode "$mode"
set_build "$build"
[ -x "$SIM" ] || die "$SIM not found: build it first (cmake --build BUILD --target torusrt-sim)"
command -v jq >/dev/null || die "jq is required"
[ -n "$results" ] || results=$EXP/results$([ "$mode" = quick ] && echo -quick)
places=(--results --results "$results")
[ -z "$doc" ] || places+=(--page --doc "$doc" --images "--doc (its img/ folder)" "$(dirname "$doc")/img")
check_places "${places[@]}"
make_folder --results "$results"
RES=$(cd "$results" && pwd)
if [ -z "$doc" ]; then
    if [ "$mode" = full ]; then doc=$REPO/docs/reproduction.md; else doc=$RES/reproduction.md; fi
fi

# One results folder per reading (RES/READING), listed together so that one parallel run per
# phase covers them all. Every list is written through experiments/output_files.py (write_file).
for p in "${READINGS[@]}"; do
    mkdir -p "$RES/$p"
    "$EXP/points.sh" "${popt[@]}" --build "$BUILD" --reading "$p" --tsv "$MODE" "$RES/$p" |
        write_file "$RES/$p/points.tsv" --results || die "points.sh failed"
    echo "$MODE" | write_file "$RES/$p/mode" --results || exit 2
done
for ph in 1 2; do  # the point lists of experiments/backend: JSON, tab, command
    for p in "${READINGS[@]}"; do
        "$EXP/points.sh" "${popt[@]}" --build "$BUILD" --reading "$p" --tsv --phase $ph "$MODE" "$RES/$p" | cut -f9,10
    done | write_file "$RES/points.phase$ph" --results || die "points.sh failed"
done
echo "$MODE" | write_file "$RES/mode" --results || exit 2
for p in "${READINGS[@]}"; do cat "$RES/$p/points.tsv"; done | write_file "$RES/points.tsv" --results || exit 2
total=$(wc -l <"$RES/points.tsv")
echo "sweep: $MODE mode, $total points, results in $RES"
RUN_POINTS_OPTS=(--runs "$RES/runs.tsv" --label "$MODE")
run_points "$RES" "sweep-$MODE" "$RES/points.phase1" "$RES/points.phase2"
status=$?
[ $status -lt 2 ] || exit 2
merge_joblogs "$RES"

if [ "$report" = 1 ]; then
    for p in "${READINGS[@]}"; do
        python3 "$EXP/report" collect "$RES/$p" || status=1
    done
    python3 "$EXP/report" plots "$RES" || status=1
    python3 "$EXP/report" reproduction --doc "$doc" "$RES" || status=1
    echo "sweep: CSVs and plots in $RES, report $doc"
fi
exit $status
