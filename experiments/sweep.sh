#!/usr/bin/env bash
# sweep.sh - the whole reproduction in one command: run every point, then collect the CSVs (experiments/report),
# draw the plots (experiments/plots/*.gp) and write the comparison with the paper (experiments/report).
#
#   experiments/sweep.sh [--quick] [--results DIR] [-j N] [--sshloginfile FILE]
#                        [--build DIR] [--doc FILE] [--no-report] [--no-clusters]
#
#   --quick              small image (32x32), few points: the CTest smoke run (seconds)
#   --results DIR        where the JSONs, CSVs, plots and logs go
#                        (default experiments/results, or experiments/results-quick)
#   -j N                 parallel jobs per machine (default: one per core)
#   --sshloginfile FILE  spread the points over the machines listed (GNU parallel's format;
#                        ':' is this machine); the repository, build and results folder must
#                        be at the same paths on every machine (a shared file system)
#   --build DIR          build folder holding torusrt-sim (default $TORUSRT_BUILD, else build/)
#   --doc FILE           the report to write (default docs/reproduction.md for the full sweep,
#                        RESULTS/reproduction.md for --quick); plots are copied beside it in img/
#   --no-report          run the points only
#   --no-clusters        leave out figures 10-12 (for builds without the cluster model)
#
# Every point runs under each timing profile (experiments/lib.sh PROFILES: calibrated, the
# default, and literal); RES/PROFILE holds that profile's JSONs, CSVs and plots, RES the point
# lists, joblogs and runs.tsv. The one-processor points (phase 1) run first, since every other point takes its T(1) from
# them. Points already done are skipped, so an interrupted or partly failed sweep is resumed by
# running the same command again. Failed points are listed with their command lines (from
# RESULTS/joblog) and the exit status is then 1; the collection step marks them in the CSVs.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

mode=full results="" jobs="" sshlogin="" build=$BUILD doc="" report=1 popt=()
while [ $# -gt 0 ]; do
    case $1 in
        --quick) mode=quick; shift ;;
        --results) results=$2; shift 2 ;;
        -j) jobs=$2; shift 2 ;;
        -j*) jobs=${1#-j}; shift ;;
        --sshloginfile) sshlogin=$2; shift 2 ;;
        --build) build=$2; shift 2 ;;
        --doc) doc=$2; shift 2 ;;
        --no-report) report=0; shift ;;
        --no-clusters) popt+=(--no-clusters); shift ;;
        -h|--help) sed -n '2,/^set -uo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
        *) die "unknown argument '$1' (see --help)" ;;
    esac
done
define_mode "$mode"
set_build "$build"
[ -x "$SIM" ] || die "$SIM not found: build it first (cmake --build BUILD --target torusrt-sim)"
command -v parallel >/dev/null || die "GNU parallel is required"
command -v jq >/dev/null || die "jq is required"
[ -n "$results" ] || results=$EXP/results$([ "$mode" = quick ] && echo -quick)
mkdir -p "$results"
RES=$(cd "$results" && pwd)
[ -n "$jobs" ] || jobs=$(nproc)
if [ -z "$doc" ]; then
    if [ "$mode" = full ]; then doc=$REPO/docs/reproduction.md; else doc=$RES/reproduction.md; fi
fi

# One results folder per timing profile (RES/PROFILE), listed together so that one parallel
# run per phase covers both.
: >"$RES/points.phase1"
: >"$RES/points.phase2"
for p in "${PROFILES[@]}"; do
    mkdir -p "$RES/$p"
    "$EXP/points.sh" "${popt[@]}" --build "$BUILD" --profile "$p" --tsv "$MODE" "$RES/$p" >"$RES/$p/points.tsv" || die "points.sh failed"
    echo "$MODE" >"$RES/$p/mode"
    "$EXP/points.sh" "${popt[@]}" --build "$BUILD" --profile "$p" --phase 1 "$MODE" "$RES/$p" >>"$RES/points.phase1"
    "$EXP/points.sh" "${popt[@]}" --build "$BUILD" --profile "$p" --phase 2 "$MODE" "$RES/$p" >>"$RES/points.phase2"
done
echo "$MODE" >"$RES/mode"
for p in "${PROFILES[@]}"; do cat "$RES/$p/points.tsv"; done >"$RES/points.tsv"
total=$(wc -l <"$RES/points.tsv")
before=0
while IFS=$'\t' read -r _ _ _ _ _ _ _ _ json _; do
    [ -s "$json" ] && before=$((before + 1))
done <"$RES/points.tsv"
hosts=local
popts=(--will-cite --halt never -j "$jobs")
if [ -n "$sshlogin" ]; then
    popts+=(--sshloginfile "$sshlogin")
    hosts="sshloginfile $(basename "$sshlogin")"
fi
echo "sweep: $MODE mode, $total points ($before already done), -j $jobs on $hosts, results in $RES"

start=$(date +%s.%N)
for ph in 1 2; do
    n=$(wc -l <"$RES/points.phase$ph")
    echo "sweep: phase $ph ($n points)$([ $ph = 1 ] && echo ': one-processor runs, T(1) for the rest')"
    parallel "${popts[@]}" --joblog "$RES/joblog.phase$ph" <"$RES/points.phase$ph" >"$RES/sweep.phase$ph.out"
done
end=$(date +%s.%N)
# CPU time of everything run so far (the points, through parallel) and the machine's load.
times >"$RES/.times"
cpu=$(awk 'NR == 2 { n = 0; for (i = 1; i <= 2; i++) { split($i, a, "m"); sub("s", "", a[2]); n += a[1] * 60 + a[2] } printf "%.1f", n }' "$RES/.times")
load1=$(cut -d" " -f1 /proc/loadavg 2>/dev/null || echo "")
{ head -n 1 "$RES/joblog.phase1"; tail -q -n +2 "$RES/joblog.phase1" "$RES/joblog.phase2"; } >"$RES/joblog"
wall=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }')

# Failed points: non-zero exit or a signal in the joblog.
awk -F'\t' 'NR > 1 && ($7 != 0 || $8 != 0) { print $7 "\t" $8 "\t" $9 }' "$RES/joblog" >"$RES/failed.tsv"
failed=$(wc -l <"$RES/failed.tsv")
after=0
while IFS=$'\t' read -r _ _ _ _ _ _ _ _ json _; do
    [ -s "$json" ] && after=$((after + 1))
done <"$RES/points.tsv"
ran=$((after - before))
[ -s "$RES/runs.tsv" ] || printf 'started_utc\tmode\tjobs\thosts\tcores\tpoints\tpoints_run\tfailed\twall_s\tcpu_s\tload1\n' >"$RES/runs.tsv"
printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u -d "@${start%.*}" +%FT%TZ)" "$MODE" "$jobs" "$hosts" \
    "$(nproc)" "$total" "$ran" "$failed" "$wall" "$cpu" "$load1" >>"$RES/runs.tsv"
echo "sweep: $ran points run, $((total - after)) missing, $failed failed, ${wall} s wall, ${cpu} s CPU (load $load1)"
if [ "$failed" -gt 0 ]; then
    echo "sweep: FAILED points (exit status, signal, command; messages in the point's .log):" >&2
    while IFS=$'\t' read -r rc sig cmd; do
        echo "  exit $rc signal $sig: $cmd" >&2
    done <"$RES/failed.tsv"
fi

status=0
[ "$failed" -eq 0 ] && [ "$after" -eq "$total" ] || status=1
if [ "$report" = 1 ]; then
    for p in "${PROFILES[@]}"; do
        python3 "$EXP/report" collect "$RES/$p" || status=1
    done
    python3 "$EXP/report" plots "$RES" || status=1
    python3 "$EXP/report" reproduction --doc "$doc" "$RES" || status=1
    echo "sweep: CSVs and plots in $RES, report $doc"
fi
exit $status
