# shellcheck shell=bash
# shellcheck disable=SC2154  # the variables of study.sh, which sources this file
# readings.sh - validation and robustness of experiments/fidelity/study.sh (sourced).
# Validation: the reproduction's points (experiments/points.sh, full; quick under --smoke) once on
# the fitted files, each cluster point the mean of its runs at every bus_arbitration value
# (experiments/report/fidelity_means.py); a robustness reading runs each point once. Robustness: the fitted reading with one unknown moved at a time, in the
# protocol's order; a reading re-runs only the points its unknown can move and takes the fitted
# reading's others (its scope, below). Readings that would start after the cap are dropped from
# the end of the list and named in RES/dropped.tsv (under --smoke, all but the first).
# Writes RES/readings.tsv (name, scope, settings) and RES/dropped.tsv (name, why, settings).

fitted_dir=$res/sweeps/fitted/calibrated
# copy_points SCOPE DIR: the fitted reading's points that SCOPE cannot move, copied into DIR:
#   all       none (the cell-step cost moves T(1) and every point)
#   timing    T(1) (n = 1 has no crossing, link, bus or second node)
#   clusters  T(1) and the flat torus (the bus)
#   flat      T(1) and the clusters (the counting rule: units of the flat points)
#   image1    image 2's points; image2: image 1's
copy_points() {
    local d keep=()
    case $1 in
        all) return 0 ;;
        timing) keep=(t1/) ;;
        clusters) keep=(t1/ fig5_6/) ;;
        flat) keep=(t1/ fig10_12/) ;;
        image1) keep=(t1/image2 fig5_6/image2 fig10_12/image2) ;;
        image2) keep=(t1/image1 fig5_6/image1 fig10_12/image1) ;;
        *) die "unknown reading scope '$1'" ;;
    esac
    for d in "${keep[@]}"; do
        mkdir -p "$2/${d%%/*}"
        find "$fitted_dir/${d%%/*}" -maxdepth 1 -type f -name "${d#*/}*" -exec cp -p {} "$2/${d%%/*}/" \;
    done
}
: >"$scratch/readings.tsv"; : >"$scratch/dropped.tsv"
ran=0
# reading NAME SCOPE VAR=VALUE...: the reproduction's points under one reading, run and collected.
reading() {
    local name=$1 scope=$2 dir=$res/sweeps/$1/calibrated ph
    shift 2
    if [ "$name" != fitted ]; then
        if [ -n "$smoke" ] && [ "$ran" -ge 1 ]; then
            printf '%s\t%s\t%s\n' "$name" "smoke mode" "$*" >>"$scratch/dropped.tsv"; return 0
        fi
        if [ $(($(date +%s) - start)) -gt "$cap" ]; then
            printf '%s\t%s\t%s\n' "$name" "cap" "$*" >>"$scratch/dropped.tsv"; return 0
        fi
        ran=$((ran + 1))
    fi
    mkdir -p "$dir"
    [ "$name" = fitted ] || copy_points "$scope" "$dir"
    env "$@" "$root/experiments/points.sh" --build "$build" --reading calibrated --tsv "$mode" "$dir" |
        write_file "$dir/points.tsv"
    echo "$mode" | write_file "$dir/mode"
    for ph in 1 2; do  # the point lists of experiments/backend: JSON, tab, command
        env "$@" "$root/experiments/points.sh" --build "$build" --reading calibrated --tsv --phase $ph "$mode" "$dir" |
            cut -f9,10 | write_file "$dir/points.phase$ph"
    done
    if [ "$name" = fitted ]; then
        # Validation: each cluster point the mean of its runs at every bus_arbitration value.
        fit means-lists "$dir/points.phase2" "$dir/points.flat" "$dir/points.replicas" "${arbitrations[@]}"
        run_points "$dir/.." "fidelity-$name" "$dir/points.phase1" "$dir/points.flat" "$dir/points.replicas" ||
            echo "study.sh: reading $name: some points failed (see $dir/..)" >&2
        fit means "$dir/points.phase2" "${arbitrations[@]}" || echo "study.sh: reading $name: some means missing" >&2
    else
        run_points "$dir/.." "fidelity-$name" "$dir/points.phase1" "$dir/points.phase2" ||
            echo "study.sh: reading $name: some points failed (see $dir/..)" >&2
    fi
    merge_joblogs "$dir/.."
    python3 "$root/experiments/report" collect "$dir" >/dev/null
    printf '%s\t%s\t%s\n' "$name" "$scope" "$*" >>"$scratch/readings.tsv"
    echo "study: reading $name done ($(($(date +%s) - start)) s)"
}
cfg="--config $dest/machines/paper-16.toml"
base=(TORUSRT_SHAPE16="$shape" TORUSRT_LB_MAP=cyclic TORUSRT_SCENE_IMAGE1="$dest/scenes/paper-image1.nff"
      TORUSRT_SCENE_IMAGE2="$dest/scenes/paper-image2.nff")
# with VAR=VALUE...: the fitted reading's settings with the given ones replaced, one a line; a
# robustness reading runs the mappings the claims judge (block and load-balancing).
with() {
    local -A v=(); local kv
    for kv in "${base[@]}" TORUSRT_POINT_ARGS="$cfg" TORUSRT_MAPS="block cyclic" "$@"; do v[${kv%%=*}]=${kv#*=}; done
    for kv in "${!v[@]}"; do printf '%s=%s\n' "$kv" "${v[$kv]}"; done
}
# robust NAME SCOPE VAR=VALUE...: one robustness reading.
robust() { local name=$1 scope=$2 e; shift 2; mapfile -t e < <(with "$@"); reading "$name" "$scope" "${e[@]}"; }
# fitted_timing NAME KEY=VALUE...: the fitted timing with keys replaced (hand-over as one cost).
fitted_timing() {
    local name=$1 kv k v t=$res/timing/reading-$1.timing
    shift
    cp "$dest/machines/timing/fitted.timing" "$scratch/t"
    for kv in "$@"; do
        k=${kv%%=*} v=${kv#*=}
        if [ "$k" = handover ]; then
            fit timing "handover=$v" | grep '^handover_' >"$scratch/h"
            grep -v '^handover_' "$scratch/t" | cat - "$scratch/h" >"$scratch/t2"
        else
            sed "s/^$k .*/$k $v/" "$scratch/t" >"$scratch/t2"
        fi
        mv "$scratch/t2" "$scratch/t"
    done
    write_file "$t" <"$scratch/t"
    echo "$t"
}
# respec SPEC KEY VALUE: a scene variant with one key moved.
respec() { echo "$1" | sed "s/\(^\|,\)$2=[^,]*/\1$2=$3/"; }

reading fitted all "${base[@]}" TORUSRT_POINT_ARGS="$cfg"
# 1. U7 the interleave; 2. U16 a ring of two's links
for mp in block-cyclic:2 block-cyclic:3; do robust "map-${mp//:/}" timing TORUSRT_LB_MAP="$mp"; done
robust ties-plus timing TORUSRT_POINT_ARGS="$cfg --route-ties plus"
# 3. U15's other values, the hand-over reset to 0 where the cost no longer allows it
for cc in "${cell_steps[@]}"; do
    [ "$cc" = "$c" ] && continue
    h=$handover; fit allowed "$cc" | tr ' ' '\n' | grep -qx "$h" || h=0
    robust "cell-step-$cc" all TORUSRT_POINT_ARGS="$cfg --timing $(fitted_timing "c$cc" cell_step_packet="$cc" handover="$h")"
done
# 4. U6's other allowed values; 5. U5's extreme pairs; 6. U4's others
for h in $(fit allowed "$c"); do
    [ "$h" = "$handover" ] || robust "handover-$h" timing TORUSRT_POINT_ARGS="$cfg --timing $(fitted_timing "h$h" handover="$h")"
done
for bm in 0.5/0.5 4/2; do
    [ "$bm" = "$bus/$memory" ] && continue
    robust "bus-${bm/\//-}" clusters \
        TORUSRT_POINT_ARGS="$cfg --timing $(fitted_timing "bus${bm/\//-}" bus_cycle="${bm%/*}" memory_access="${bm#*/}")"
done
for sh in 4x2x2 2x2x4 4x4 16; do [ "$sh" = "$shape" ] || robust "shape-$sh" timing TORUSRT_SHAPE16="$sh"; done
# 7. U8; 8. U1
for acc in 4/4/0 2/2/0 0/4/0 4/4/36; do
    [ "$acc" = "$header/$entry/$record" ] && continue
    IFS=/ read -r hb eb ob <<<"$acc"
    robust "memory-$hb-$eb-$ob" timing \
        TORUSRT_POINT_ARGS="$cfg --cell-header-bytes $hb --list-entry-bytes $eb --object-record-bytes $ob"
done
r2=per-plane; [ "$rule" = per-plane ] && r2=sequential
robust "rule-$r2" flat TORUSRT_POINT_ARGS="$cfg --preprocess-count $r2"
# 9.-11. the scene unknowns, one image at a time
scene_reading() {  # scene_reading IMAGE KEY VALUES...
    local i=$1 k=$2 v spec; shift 2
    spec=$spec1; [ "$i" = 2 ] && spec=$spec2
    for v in "$@"; do
        [ "$(respec "$spec" "$k" "$v")" = "$spec" ] && continue
        robust "image$i-$k-$v" "image$i" "TORUSRT_SCENE_IMAGE$i=$(scene "$i" "$(respec "$spec" "$k" "$v")")"
    done
}
scene_reading 1 layout "${layouts[@]}"
scene_reading 1 scale "${scales[@]}"
scene_reading 1 lights "${image1_lights[@]}"
scene_reading 1 margin "${image1_margins[@]}"
scene_reading 2 plane "${image2_planes[@]}"
scene_reading 2 radius "${image2_radii[@]}"
scene_reading 2 lights "${image2_lights[@]}"
scene_reading 2 margin "${image2_margins[@]}"
done_file readings.tsv; done_file dropped.tsv
