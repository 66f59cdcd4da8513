#!/usr/bin/env bash
# study.sh - the error-against-run-time study of docs/design.md section 8, end to end:
#   1. quantum.sh  - LT at growing quanta against AT (both paper scenes, 144x144, 4x2x2, 4x4x4, 8x8x8)
#   2. pruning.sh  - max-depth 0..8 and min-weight 1/512..1/8 against the full-depth image
#   3. the report  - docs/img/error-*.png and docs/error-vs-runtime.md (python3 experiments/report
#                    error-vs-runtime: experiments/report/, plots experiments/plots/error-*.gp)
#
# Usage: study.sh [--build DIR] [--results DIR] [--doc FILE] [--img-dir DIR] [--reps N]
#                 [--only quantum|pruning|report] [--quick]
#                 [--backend local|ssh:HOSTFILE|slurm] [-j JOBS] [--slurm-args "..."] [--per-task K]
#   --build DIR     folder with torusrt-sim and torusrt-render (default $TORUSRT_BUILD, else REPO/build)
#   --results DIR   where the CSVs go (default experiments/error_vs_runtime/results)
#   --doc FILE      the document (default docs/error-vs-runtime.md); --img-dir its plots (docs/img);
#                   neither in scenes/, machines/, timing/, experiments/ or RESULTS (but
#                   RESULTS/NAME.md and RESULTS/img), nor the page a file the run reads: exit 2
#   --reps N        timed repetitions per point (default: 5 for the quantum study, 3 for pruning)
#   --only STEP     run one step (report: regenerate the document from the existing CSVs)
#   --quick         a smoke run: paper-image2 at 48x48 on 4x2x2 only, one repetition, a few
#                   quanta; never docs/: the CSVs, the page (error-vs-runtime.md) and its plots
#                   (img/) go into --results DIR, or a temporary folder removed at the end, unless
#                   --doc / --img-dir name other places
#   --backend ...   where the points run (experiments/backend; docs/cluster-runs.md): a point
#                   is one scene and torus size of quantum.sh, or one scene of pruning.sh, its
#                   CSV in RESULTS/points/ (done when it is there, so a re-run resumes; delete
#                   the folder to recompute); -j JOBS points at once (default 1, since the
#                   points measure wall times)
# Takes about 5 minutes on 2 cores with the defaults.
set -euo pipefail
# shellcheck source=experiments/error_vs_runtime/common.sh
source "$(dirname "$0")/common.sh"
source "$(dirname "$0")/../lib.sh"

RESULTS=$EVR_DIR/results
DOC=$REPO/docs/error-vs-runtime.md
IMG=$REPO/docs/img
REPS=""
ONLY=""
QUICK=0
ARGS_SEEN=()
JOBS=1
while [ $# -gt 0 ]; do
  if backend_option "$@"; then shift "$SHIFT"; continue; fi
  case $1 in
    --build|--results|--doc|--img-dir|--reps|--only) need_value "$@" ;;
  esac
  case $1 in
    --build) BUILD=$2; shift 2 ;;
    --results) RESULTS=$2; ARGS_SEEN+=(results); shift 2 ;;
    --doc) DOC=$2; ARGS_SEEN+=(doc); shift 2 ;;
    --img-dir) IMG=$2; ARGS_SEEN+=(img); shift 2 ;;
    --reps) REPS=$2; shift 2 ;;
    --only) ONLY=$2; shift 2 ;;
    --quick) QUICK=1; shift ;;
    -h|--help) show_help '^set -euo' ;;
    *) die "unknown option $1 (see --help)" ;;
  esac
done
case $ONLY in ""|quantum|pruning|report) ;; *) die "--only: quantum, pruning or report" ;; esac
[ "$ONLY" = report ] || set_build "$BUILD" torusrt-render  # before any point runs
export TORUSRT_BUILD=$BUILD

qargs=() pargs=() SCENES="paper-image1 paper-image2" IPS="4x2x2 4x4x4" QIPS="4x2x2 4x4x4 8x8x8"
command_line="experiments/error_vs_runtime/study.sh"
seen() { [[ " ${ARGS_SEEN[*]-} " == *" $1 "* ]]; }
places=()  # a quick run's own temporary results folder needs no check
[ "$QUICK" = 1 ] && ! seen results || places+=(--results --results "$RESULTS")
! seen doc || places+=(--page --doc "$DOC")
! seen img || places+=(--images --img-dir "$IMG")
check_places "${places[@]}"
if [ "$QUICK" = 1 ]; then
  # A smoke run never writes docs/: its page and plots go into its results folder (a temporary
  # one, removed at the end, without --results) unless --doc / --img-dir name other places.
  if ! seen results; then
    QTMP=$(mktemp -d)
    trap 'rm -rf "$QTMP"' EXIT
    RESULTS=$QTMP/results
  fi
  seen doc || DOC=$RESULTS/error-vs-runtime.md
  seen img || IMG=$RESULTS/img
  SCENES=paper-image2 IPS=4x2x2 QIPS=4x2x2
  qargs=(--size 48x48 --quanta "0 1ms 100ms 1s 100s" --reps "${REPS:-1}")
  pargs=(--size 48x48 --depths "0 2 4 8" --weights "1/512 1/64 1/8" --reps "${REPS:-1}")
  command_line+=" --quick"
else
  [ -n "$REPS" ] && qargs=(--reps "$REPS") && pargs=(--reps "$REPS")
fi
make_folder --results "$RESULTS" && mkdir -p "$RESULTS/points"
[ "$DOC" != "$RESULTS/error-vs-runtime.md" ] || DOC=$(cd "$RESULTS" && pwd)/error-vs-runtime.md
[ "$IMG" != "$RESULTS/img" ] || IMG=$(cd "$RESULTS" && pwd)/img
RESULTS=$(cd "$RESULTS" && pwd)
work=$RESULTS/points
# point_line STEP CSV ARGS...: one line of a point list: done when CSV exists.
point_line() { printf '%s\t%s\n' "$2" "$(printf '%q ' "$EVR_DIR/$1.sh" --build "$BUILD" --out "$2" "${@:3}")"; }
# The lists and CSVs are written through experiments/output_files.py (write_file).
for s in $SCENES; do
  if [ -z "$ONLY" ] || [ "$ONLY" = quantum ]; then
    for ips in $QIPS; do point_line quantum "$work/quantum-$s-$ips.csv" "${qargs[@]}" --scenes "$s" --ips "$ips"; done
  fi
done | write_file "$work/quantum.list"
for s in $SCENES; do
  if [ -z "$ONLY" ] || [ "$ONLY" = pruning ]; then
    point_line pruning "$work/pruning-$s.csv" "${pargs[@]}" --scenes "$s" --ips "$IPS"
  fi
done | write_file "$work/pruning.list"
# merge_csv LIST OUT: the CSVs of LIST's points, in its order, under one header.
merge_csv() {
  local csv _ first=1
  [ -s "$1" ] || return 0
  while IFS=$'\t' read -r csv _; do
    if [ $first = 1 ]; then cat "$csv"; first=0; else tail -n +2 "$csv"; fi
  done <"$1" | write_file "$2" --results
}
if [ -z "$ONLY" ] || [ "$ONLY" != report ]; then
  cat "$work/quantum.list" "$work/pruning.list" | write_file "$work/points.list"
  run_points "$work/run" error-vs-runtime "$work/points.list"
  merge_csv "$work/quantum.list" "$RESULTS/quantum.csv"
  merge_csv "$work/pruning.list" "$RESULTS/pruning.csv"
fi
if [ -z "$ONLY" ] || [ "$ONLY" = report ]; then
  python3 "$REPO/experiments/report" error-vs-runtime --quantum "$RESULTS/quantum.csv" \
    --pruning "$RESULTS/pruning.csv" --doc "$DOC" --img-dir "$IMG" --command "$command_line"
fi
[ "$QUICK" = 1 ] && [ -f "$DOC" ] && [ "${QTMP-}" != "" ] && [[ "$DOC" == "$QTMP"* ]] &&
  echo "study: quick run only; its document was written to a temporary folder and removed" >&2
exit 0
