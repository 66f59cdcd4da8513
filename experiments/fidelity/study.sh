#!/usr/bin/env bash
# study.sh - the fidelity study: the paper's unknowns fitted on its hard numbers in stages, the
# other claims judged on the fitted machine, and each claim judged again with every unknown
# moved one at a time. Follows the protocol in experiments/fidelity/protocol.md; writes
# machines/*.toml, machines/timing/fitted.timing and docs/fidelity.md.
#
#   bash experiments/fidelity/study.sh [--build DIR] [-j N] [--stage 1] [--results DIR]
#          [--backend local|ssh:HOSTFILE|slurm] [--slurm-args "..."] [--per-task K]
#
#   --build DIR   build folder holding torusrt-sim and torusrt-render (default build/)
#   -j N          runs in flight (default 2)
#   --stage 1     run the units fit alone (the renderer only) and print its choice
#   --results DIR the folder of the runs and their tables (default experiments/fidelity/results/)
#   --backend     where the runs go (experiments/backend, docs/cluster-runs.md): this machine
#                 (default), the hosts of an ssh login file, or a Slurm job array; --slurm-args
#                 passes sbatch options, --per-task batches K runs to a Slurm task
#
# Every run goes through experiments/run_point.sh into the results folder, and a run
# is done when its JSON is there: re-running the study after an interruption recomputes only
# the missing runs; remove the results folder to start again.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
here=$EXP/fidelity root=$REPO
build=$BUILD JOBS=2 only="" res=$here/results
while [ $# -gt 0 ]; do
    if backend_option "$@"; then shift "$SHIFT"; continue; fi
    case $1 in
        --build|--stage|--results) [ $# -ge 2 ] && [ -n "$2" ] || die "$1 needs a value (not an empty one)" ;;
    esac
    case $1 in
        --build) build=$2; shift 2 ;;
        --stage) only=$2; shift 2 ;;
        --results) res=$2; shift 2 ;;
        -h|--help) sed -n '2,/^set -e/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
        *) die "unknown argument '$1' (see --help)" ;;
    esac
done
set_build "$build"
build=$BUILD jobs=${JOBS:-$BACKEND}
sim=$build/torusrt-sim render=$build/torusrt-render
mkdir -p "$res"
res=$(cd "$res" && pwd) runs=$res/runs
mkdir -p "$runs" "$res/timing"
fit() { python3 "$root/experiments/report" fidelity "$@"; }
start=$(date +%s)

# The protocol's candidates.
layouts=(planar planar-z cube tree)
rules=(sequential per-plane bounding-sphere)
image2s=(floor wall)
shapes=(4x2x2 2x2x4 4x4 16)
maps=(cyclic block-cyclic:2 block-cyclic:3)
handovers=(0 580 2180)
buses=(0.5 1 2 4)
memories=(0.5 1 2)
scene_of() {
    case $1 in
        planar-z) echo "$root/scenes/paper-image1.nff" ;;
        floor) echo "$root/scenes/paper-image2.nff" ;;
        wall) echo "$root/scenes/paper-image2-wall.nff" ;;
        *) echo "$root/scenes/paper-image1-$1.nff" ;;
    esac
}
# handover_send and handover_receive of a hand-over cost (2180 = creation + analysis).
handover_keys() {
    case $1 in
        0) printf 'handover_send 0\nhandover_receive 0\n' ;;
        580) printf 'handover_send 0\nhandover_receive 580\n' ;;
        2180) printf 'handover_send 1600\nhandover_receive 580\n' ;;
    esac
}
# runs LIST: run the points of LIST (JSON, tab, command) on the chosen backend, its state beside
# the list.
runs() {
    local name; name=$(basename "$1" .list)
    run_points "$res/run-$name" "fidelity-$name" "$1" || die "some runs of $1 failed (see $res/run-$name)"
}
# Files built a line at a time grow in a private scratch folder; done NAME writes RES/NAME from
# it through experiments/output_files.py (atomic, never over an input), like every study output.
scratch=$(mktemp -d "$res/.lines.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
done_file() { write_file "$res/$1" <"$scratch/$1"; }
# point JSON ARGS...: the list line of one experiments/run_point.sh run writing JSON.
point() { printf '%s\t' "$1"; printf '%q ' "$root/experiments/run_point.sh" "$@"; echo; }

# ---- stage 1: units (layout x counting rule, the renderer alone)
: >"$scratch/stage1.tsv" ; : >"$scratch/stage1.list"
for l in "${layouts[@]}"; do
    for r in "${rules[@]}"; do
        j=$runs/s1-$l-$r.json
        printf '%s\t%s\t%s\n' "$l" "$r" "$j" >>"$scratch/stage1.tsv"
        # The renderer writes its files only when it succeeds: the JSON marks the run done.
        printf '%s\t%q %q --size 8x8 --preprocess-count %q -q -o %q --stats %q\n' "$j" "$render" \
            "$(scene_of "$l")" "$r" "${j%.json}.png" "$j" >>"$scratch/stage1.list"
    done
done
done_file stage1.tsv; done_file stage1.list
runs "$res/stage1.list"
read -r layout rule < <(fit fit1 "$res")
echo "study: stage 1 chose layout $layout, counting rule $rule"
[ "$only" = 1 ] && exit 0
image1=$(scene_of "$layout")

# One-processor runs: T(1) of every scene a later stage runs (no hand-over, no bus at n = 1).
: >"$scratch/t1.list"
for s in "$layout" "${image2s[@]}"; do
    point "$runs/t1-$s.json" -- "$sim" "$(scene_of "$s")" --ips 1 >>"$scratch/t1.list"
done
done_file t1.list
runs "$res/t1.list"

# ---- stage 2: the penalty (bus and memory timing), m = 64, the unfitted 4x2x2, cyclic, hand-over 0
: >"$scratch/stage2.tsv" ; : >"$scratch/stage2.list"
for b in "${buses[@]}"; do
    for m in "${memories[@]}"; do
        t=$res/timing/bus-$b-$m.timing
        printf 'bus_cycle %s\nmemory_access %s\n' "$b" "$m" | write_file "$t"
        for s in "$layout" floor; do
            img=image1; [ "$s" = floor ] && img=image2
            for d in replicated shared; do
                j=$runs/s2-$s-$b-$m-$d.json
                printf '%s\t%s\t%s\t%s\t%s\n' "$b" "$m" "$img" "$d" "$j" >>"$scratch/stage2.tsv"
                point "$j" --t1-from "$runs/t1-$s.json" -- "$sim" "$(scene_of "$s")" --timing "$t" \
                    --ips 4x2x2 --map cyclic --cluster 64 --data "$d" >>"$scratch/stage2.list"
            done
        done
    done
done
done_file stage2.tsv; done_file stage2.list
runs "$res/stage2.list"
read -r bus memory < <(fit fit2 "$res")
echo "study: stage 2 chose bus_cycle $bus us, memory_access $memory us"

# ---- stage 3: the 1024 times (arrangement x interleave x hand-over x image 2), replicated
: >"$scratch/stage3.tsv" ; : >"$scratch/stage3.list"
for h in "${handovers[@]}"; do
    t=$res/timing/fit-$h.timing
    { printf 'bus_cycle %s\nmemory_access %s\n' "$bus" "$memory"; handover_keys "$h"; } | write_file "$t"
    for sh in "${shapes[@]}"; do
        for mp in "${maps[@]}"; do
            for s in "$layout" "${image2s[@]}"; do
                img=image2; [ "$s" = "$layout" ] && img=image1
                j=$runs/s3-$s-$h-$sh-${mp//:/}.json
                printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$sh" "$mp" "$h" "$img" "$s" "$j" >>"$scratch/stage3.tsv"
                point "$j" --t1-from "$runs/t1-$s.json" -- "$sim" "$(scene_of "$s")" --timing "$t" \
                    --ips "$sh" --map "$mp" --cluster 64 --data replicated >>"$scratch/stage3.list"
            done
        done
    done
done
done_file stage3.tsv; done_file stage3.list
runs "$res/stage3.list"
read -r shape lbmap handover image2 < <(fit fit3 "$res")
echo "study: stage 3 chose $shape, $lbmap, hand-over $handover us, image 2 $image2"

# ---- the fitted machine: its files, and the penalty measured again on it
fit machines "$res" "$root/machines" --rule "$rule" --bus "$bus" --memory "$memory" --shape "$shape" \
    --map "$lbmap" --handover "$handover"
: >"$scratch/check.tsv" ; : >"$scratch/check.list"
for s in "$layout" "$image2"; do
    img=image2; [ "$s" = "$layout" ] && img=image1
    for d in replicated shared; do
        j=$runs/check-$s-$d.json
        printf '%s\t%s\t%s\n' "$img" "$d" "$j" >>"$scratch/check.tsv"
        point "$j" --t1-from "$runs/t1-$s.json" -- "$sim" "$(scene_of "$s")" \
            --config "$root/machines/paper-1024-$d.toml" >>"$scratch/check.list"
    done
done
done_file check.tsv; done_file check.list
runs "$res/check.list"

# ---- validation and robustness: the reproduction's points under each reading
# reading NAME VAR=VALUE...: the reproduction's points under one reading, run and collected;
# a robustness reading is dropped (listed in RES/dropped.tsv) once the study has run past the cap,
# 30 minutes of wall time unless TORUSRT_STUDY_CAP_S says otherwise (a busy machine).
cap=${TORUSRT_STUDY_CAP_S:-1800}
: >"$scratch/readings.tsv" ; : >"$scratch/dropped.tsv"
reading() {
    local name=$1 dir=$res/sweeps/$1/calibrated ph
    shift
    if [ "$name" != fitted ] && [ $(($(date +%s) - start)) -gt "$cap" ]; then
        printf '%s\t%s\n' "$name" "$*" >>"$scratch/dropped.tsv"
        return 0
    fi
    mkdir -p "$dir"
    # The machine file's timing file sets every key, and the variables name the scenes and the
    # mapping: the reading given only names the results folder.
    env "$@" "$root/experiments/points.sh" --build "$build" --reading calibrated --tsv full "$dir" |
        write_file "$dir/points.tsv"
    echo full | write_file "$dir/mode"
    for ph in 1 2; do  # the point lists of experiments/backend: JSON, tab, command
        env "$@" "$root/experiments/points.sh" --build "$build" --reading calibrated --tsv --phase $ph full "$dir" |
            cut -f9,10 | write_file "$dir/points.phase$ph"
    done
    run_points "$dir/.." "fidelity-$name" "$dir/points.phase1" "$dir/points.phase2" ||
        echo "study.sh: reading $name: some points failed (see $dir/..)" >&2
    merge_joblogs "$dir/.."
    python3 "$root/experiments/report" collect "$dir" >/dev/null
    printf '%s\t%s\n' "$name" "$*" >>"$scratch/readings.tsv"
    echo "study: reading $name done ($(($(date +%s) - start)) s)"
}
base=(TORUSRT_SHAPE16="$shape" TORUSRT_LB_MAP="$lbmap" TORUSRT_SCENE_IMAGE1="$image1"
      TORUSRT_SCENE_IMAGE2="$(scene_of "$image2")")
cfg="--config $root/machines/paper-16.toml"
# with VAR=VALUE...: the fitted reading with the given variables replaced, one a line; a
# robustness reading runs only the mappings the claims judge (block and load-balancing).
with() { local -A v=(); local kv; for kv in "${base[@]}" TORUSRT_MAPS="block cyclic" "$@"; do v[${kv%%=*}]=${kv#*=}; done
         for kv in "${!v[@]}"; do printf '%s=%s\n' "$kv" "${v[$kv]}"; done; }
reading fitted "${base[@]}" TORUSRT_POINT_ARGS="$cfg"
# The robustness readings, in the protocol's order of unknowns.
for r in "${rules[@]}"; do [ "$r" = "$rule" ] || { mapfile -t e < <(with TORUSRT_POINT_ARGS="$cfg --preprocess-count $r"); reading "rule-$r" "${e[@]}"; }; done
for l in "${layouts[@]}"; do [ "$l" = "$layout" ] || { mapfile -t e < <(with TORUSRT_SCENE_IMAGE1="$(scene_of "$l")" TORUSRT_POINT_ARGS="$cfg"); reading "layout-$l" "${e[@]}"; }; done
for s in "${image2s[@]}"; do [ "$s" = "$image2" ] || { mapfile -t e < <(with TORUSRT_SCENE_IMAGE2="$(scene_of "$s")" TORUSRT_POINT_ARGS="$cfg"); reading "image2-$s" "${e[@]}"; }; done
for sh in "${shapes[@]}"; do [ "$sh" = "$shape" ] || { mapfile -t e < <(with TORUSRT_SHAPE16="$sh" TORUSRT_POINT_ARGS="$cfg"); reading "shape-$sh" "${e[@]}"; }; done
for bm in 0.5/0.5 4/2; do
    [ "$bm" = "$bus/$memory" ] && continue
    t=$res/timing/fitted-bus${bm/\//-}.timing
    { grep -v '^bus_cycle\|^memory_access' "$root/machines/timing/fitted.timing"
      printf 'bus_cycle %s\nmemory_access %s\n' "${bm%/*}" "${bm#*/}"; } | write_file "$t"
    mapfile -t e < <(with TORUSRT_POINT_ARGS="$cfg --timing $t"); reading "bus-${bm/\//-}" "${e[@]}"
done
for h in "${handovers[@]}"; do
    [ "$h" = "$handover" ] && continue
    t=$res/timing/fitted-h$h.timing
    { grep -v '^handover_' "$root/machines/timing/fitted.timing"; handover_keys "$h"; } | write_file "$t"
    mapfile -t e < <(with TORUSRT_POINT_ARGS="$cfg --timing $t"); reading "handover-$h" "${e[@]}"
done
for mp in "${maps[@]}"; do [ "$mp" = "$lbmap" ] || { mapfile -t e < <(with TORUSRT_LB_MAP="$mp" TORUSRT_POINT_ARGS="$cfg"); reading "map-${mp//:/}" "${e[@]}"; }; done
for acc in "2 2 0" "0 4 0" "4 4 36"; do
    read -r hb eb ob <<<"$acc"
    mapfile -t e < <(with TORUSRT_POINT_ARGS="$cfg --cell-header-bytes $hb --list-entry-bytes $eb --object-record-bytes $ob")
    reading "memory-$hb-$eb-$ob" "${e[@]}"
done
done_file readings.tsv; done_file dropped.tsv
end=$(date +%s)
printf '%s\t%s\t%s\t%s\t%s\n' "$(date -u -d "@$start" +%FT%TZ)" "$jobs" "$((end - start))" \
    "$(cut -d' ' -f1 /proc/loadavg)" "$cap" | write_file "$res/wall.tsv"
fit page "$res" "$root/docs/fidelity.md"
echo "study: docs/fidelity.md written ($((end - start)) s)"
