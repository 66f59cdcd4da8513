#!/usr/bin/env bash
# study.sh - the fidelity study, round two: the paper's unknowns fitted on its hard numbers in
# five stages, the other claims judged on the fitted machine, and each claim judged again with one
# unknown moved at a time. Runs docs/fidelity-protocol.md exactly.
#
#   bash experiments/fidelity/study.sh [--build DIR] [-j N] [--results DIR] [--smoke] [--stage 1]
#          [--backend local|ssh:HOSTFILE|slurm] [--slurm-args "..."] [--per-task K]
#
# A full run (about 30 minutes of both cores) writes:
#   scenes/paper-image1.nff, scenes/paper-image2.nff   the fitted scene variants
#   machines/paper-16.toml, paper-1024-replicated.toml, paper-1024-shared.toml,
#   machines/paper-192-replicated.toml, paper-192-shared.toml   cyclic, route-ties split
#   machines/timing/fitted.timing                     the fitted timing, every key
#   docs/fidelity.md                                  the page: three counts, roles, stage tables
# and keeps its runs and tables in the results folder (units.tsv, t1.tsv, stage2.tsv, stage3.tsv,
# stage4.tsv, residuals.tsv, readings.tsv, dropped.tsv, sweeps/READING/).
#
#   --build DIR   build folder holding torusrt-sim, torusrt-render and torusrt-genscenes (default build/)
#   -j N          runs in flight (default 2)
#   --results DIR the folder of the runs and their tables (default experiments/fidelity/results/,
#                 experiments/fidelity/results-smoke/ under --smoke); one mode's runs a folder
#   --smoke       the pipeline end to end in about a minute: 16x16 images, two image 1 layouts,
#                 two bus pairs, two arbitration values, clusters of 4, the reproduction's quick
#                 points, one robustness reading; it writes everything, scenes, machines and page
#                 too, under RESULTS/out/ only (never scenes/, machines/ or docs/)
#   --stage 1     run stage 1 alone (the scene work and cell-step cost) and print its choice
#   --backend     where the runs go (experiments/backend, docs/cluster-runs.md)
#   TORUSRT_STUDY_CAP_S  the cap (default 1800 s of wall time): robustness readings that would
#                 start after it are dropped from the end of the protocol's list and named on the page
#
# Every run goes through experiments/run_point.sh into the results folder, and a run is done when
# its JSON is there: re-running after an interruption recomputes only the missing runs.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
here=$EXP/fidelity root=$REPO
build=$BUILD JOBS=2 res=$here/results smoke="" only=""
while [ $# -gt 0 ]; do
    if backend_option "$@"; then shift "$SHIFT"; continue; fi
    case $1 in
        --build|--results|--stage) need_value "$@" ;;
    esac
    case $1 in
        --build) build=$2; shift 2 ;;
        --results) res=$2; shift 2 ;;
        --smoke) smoke=--smoke; shift ;;
        --stage) [ "$2" = 1 ] || die "--stage takes 1 (stage 1 alone), not '$2'"; only=1; shift 2 ;;
        -h|--help) show_help '^set -e' ;;
        *) die "unknown argument '$1' (see --help)" ;;
    esac
done
set_build "$build" torusrt-render torusrt-genscenes
build=$BUILD jobs=${JOBS:-$BACKEND}
sim=$build/torusrt-sim render=$build/torusrt-render gen=$build/torusrt-genscenes
[ -x "$gen" ] || die "$gen not found (build torusrt-genscenes first)"
cap=${TORUSRT_STUDY_CAP_S:-1800}
[[ $cap =~ ^[0-9]+$ ]] || die "TORUSRT_STUDY_CAP_S must be a whole number of seconds, not '$cap'"
[ -z "$smoke" ] || [ "$res" != "$here/results" ] || res=$here/results-smoke
check_places --results --results "$res"
make_folder --results "$res"
res=$(cd "$res" && pwd) runs=$res/runs
# A results folder holds one mode's runs (their sizes differ under the same names).
want=${smoke:+smoke}; want=${want:-full}
if [ -s "$res/study-mode" ]; then
    [ "$(cat "$res/study-mode")" = "$want" ] ||
        die "$res holds a $(cat "$res/study-mode") run's results; give this $want run another --results"
else
    echo "$want" | write_file "$res/study-mode"
fi
mkdir -p "$runs" "$res/timing" "$res/scenes"
fit() { python3 "$root/experiments/report" fidelity "$@"; }
start=$(date +%s)
# The candidate lists (experiments/report/fidelity_stages.py, the smoke mode's when --smoke).
eval "$(fit lists $smoke)"
if [ -n "$smoke" ]; then
    size=16x16 mode=quick dest=$res/out
else
    size=144x144 mode=full dest=$root
fi
mkdir -p "$dest/scenes" "$dest/machines" "$dest/docs"

runs() {
    local name; name=$(basename "$1" .list)
    run_points "$res/run-$name" "fidelity-$name" "$1" || die "some runs of $1 failed (see $res/run-$name)"
}
# Tables built a line at a time grow in a private scratch folder; done_file NAME writes RES/NAME.
scratch=$(mktemp -d "$res/.lines.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
done_file() { write_file "$res/$1" <"$scratch/$1"; }
point() { printf '%s\t' "$1"; printf '%q ' "$root/experiments/run_point.sh" "$@"; echo; }
# stem IMAGE SPEC: a variant's file name; scene IMAGE SPEC: its file, generated once.
stem() { local s=${2//=/-}; echo "i$1-${s//,/_}"; }
scene() {
    local f; f=$res/scenes/$(stem "$1" "$2").nff
    [ -s "$f" ] || "$gen" --variant "paper-image$1" "$2" "$res/scenes" "$(stem "$1" "$2")" >/dev/null
    echo "$f"
}
# timing NAME KEY=VALUE...: RES/timing/NAME.timing, the calibrated table with the keys set. Called
# as t=$(timing ...): a failed step returns its status (a command substitution does not inherit
# set -e), and nothing is written then.
timing() {
    local f=$res/timing/$1.timing text
    shift
    text=$(fit timing "$@") || return
    printf '%s\n' "$text" | write_file "$f" || return
    echo "$f"
}
common=(--size "$size" --map cyclic --route-ties split)

source "$here/fit_scenes.sh"     # stage 1: sets spec1 rule spec2 c, image1 image2, t1json1 t1json2
[ "$only" = 1 ] && exit 0
source "$here/fit_machine.sh"    # stages 2-5: sets bus memory shape handover header entry record
source "$here/readings.sh"       # validation and robustness: RES/readings.tsv, RES/dropped.tsv
end=$(date +%s)
printf '%s\t%s\t%s\t%s\t%s\n' "$(date -u -d "@$start" +%FT%TZ)" "$jobs" "$((end - start))" \
    "$(cut -d' ' -f1 /proc/loadavg)" "$cap" | write_file "$res/wall.tsv"
fit page "$res" "$dest/docs/fidelity.md" $smoke
echo "study: $dest/docs/fidelity.md written ($((end - start)) s)"
