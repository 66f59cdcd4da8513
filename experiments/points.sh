#!/usr/bin/env bash
# points.sh - print the reproduction's points, one command line per point.
#
#   experiments/points.sh [--build DIR] [--phase 1|2|all] [--tsv] [--no-clusters]
#                         [--reading fitted|calibrated|literal] full|quick RESULTS_DIR
#
# Every point runs under the reading given (experiments/lib.sh use_reading: a timing profile, the
# image 1 scene and the load-balancing mapping; default fitted): the sweep lists each reading into
# its own RESULTS_DIR (experiments/results/READING). A mapping that runs what the load-balancing
# points run (block-cyclic:3 under fitted) is left out.
# Phase 1 is the one-processor run of each scene (RESULTS/t1/<scene>.json); every phase-2
# point reads its T(1) from there (--t1-from), so phase 1 must finish first. Each command runs
# experiments/run_point.sh, which writes RESULTS/<fig>/<point>.json (and .png) through a temporary
# name and skips the point if the JSON is already there, so re-running a list is cheap.
# Lines are independent: hand them to GNU parallel, ssh workers or a Slurm array as they are.
# Phase 2 lists the costliest points first so that parallel's workers finish together.
# --tsv prints fig, name, scene, mapping, n, shape, m, data, json, command (tab-separated)
# instead: the collection step (experiments/report collect) reads that list to find missing points. --no-clusters leaves out
# figures 10-12.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"

phase=all tsv=0 build=$BUILD clusters=1 reading=${READINGS[0]}
while [ $# -gt 0 ]; do
    case $1 in
        --build|--phase|--reading) need_value "$@" ;;
    esac
    case $1 in
        --build) build=$2; shift 2 ;;
        --phase) phase=$2; shift 2 ;;
        --tsv) tsv=1; shift ;;
        --no-clusters) clusters=0; shift ;;
        --reading) reading=$2; shift 2 ;;
        -h|--help) show_help '^set -e' ;;
        -*) die "unknown option '$1'" ;;
        *) break ;;
    esac
done
[ $# -eq 2 ] || die "usage: points.sh [--build DIR] [--phase 1|2|all] [--tsv] [--no-clusters] [--reading R] full|quick RESULTS_DIR"
case $phase in 1|2|all) ;; *) die "--phase must be 1, 2 or all" ;; esac
use_reading "$reading"
define_mode "$1"
[ "$clusters" = 1 ] || CLUSTER_SCENES=()
set_build "$build"
[ -n "$2" ] || die "RESULTS_DIR: an empty value (name a folder)"
[ ! -e "$2" ] || [ -d "$2" ] || die "RESULTS_DIR '$2': is a file, not a folder"
mkdir -p "$2"
RES=$(cd "$2" && pwd)

# emit FIG NAME SCENE MAPPING N SHAPE M DATA T1JSON SIMARGS...
emit() {
    local fig=$1 name=$2 scene=$3 map=$4 n=$5 shape=$6 m=$7 data=$8 t1=$9
    shift 9
    local json=$RES/$fig/$name.json cmd
    cmd=$(printf '%q ' "$EXP/run_point.sh" "$json")
    [ -n "$t1" ] && cmd+=$(printf '%q ' --t1-from "$t1")
    cmd+=$(printf '%q ' -- "$SIM" "$(scene_file "$scene")" --size "$SIZE" --timing-profile "$PROFILE" "${READING_ARGS[@]}" "${POINT_ARGS[@]}" "$@")
    cmd=${cmd% }
    if [ "$tsv" = 1 ]; then
        printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$fig" "$name" "$scene" "$map" "$n" "$shape" "$m" "$data" "$json" "$cmd"
    else
        printf '%s\n' "$cmd"
    fi
}

if [ "$phase" != 2 ]; then
    for s in "${SCENES[@]}"; do
        emit t1 "$s" "$s" cyclic 1 1x1x1 1 replicated "" --ips 1x1x1 --map cyclic
    done
fi
if [ "$phase" != 1 ]; then
    # Figures 10-12: 16 clusters, m processors each, shared or replicated object data.
    for ((i = ${#MLIST[@]} - 1; i >= 0; i--)); do
        m=${MLIST[i]}
        for s in "${CLUSTER_SCENES[@]}"; do
            for d in "${DATAS[@]}"; do
                emit fig10_12 "$s-$d-m$m" "$s" cyclic "$((CLUSTER_NODES * m))" "$CLUSTER_SHAPE" "$m" "$d" \
                    "$RES/t1/$s.json" --ips "$CLUSTER_SHAPE" --map "${MAPARG[cyclic]}" --cluster "$m" --data "$d"
            done
        done
    done
    # Figures 5-8: IP count x mapping x scene on a flat 3D torus.
    for ((i = ${#NLIST[@]} - 1; i >= 0; i--)); do
        n=${NLIST[i]}
        for s in "${SCENES[@]}"; do
            for map in "${MAPS[@]}"; do
                [ "$map" != cyclic ] && [ "${MAPARG[$map]}" = "${MAPARG[cyclic]}" ] && continue
                emit fig5_6 "$s-$map-n$n" "$s" "$map" "$n" "${SHAPE[$n]}" 1 replicated \
                    "$RES/t1/$s.json" --ips "${SHAPE[$n]}" --map "${MAPARG[$map]}"
            done
        done
    done
fi
