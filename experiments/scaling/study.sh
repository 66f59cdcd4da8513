#!/usr/bin/env bash
# Scaling study: image time, efficiency and data memory against the number of processors (16,
# 64, 512, 4096) on both paper scenes, cones-and-patches and facing-mirrors, for flat tori
# (cyclic, cost, cost with replicated hot cells at budgets 0.5 and 1.0, scatter, scatter with its
# hottest cells cut at budget 0.5; cyclic and both scatters again with --queue-order rays-first)
# and clusters of m = 4,
# 16 and 64 processors at the same total (wherever there are at least 4 nodes; replicated and
# shared data; cyclic and cost mapping), the default (fitted) profile; plus the busy time per node of
# paper-image2 at 512 IPs before and after replication, and the share of busy IPs over time of
# paper-image1 at 512 IPs under both queue orders. Writes docs/scaling.md and docs/scaling/.
# Usage: bash experiments/scaling/study.sh [--build DIR] [--backend local|ssh:HOSTFILE|slurm]
#          [-j JOBS] [--slurm-args "..."] [--per-task K] [BUILD_DIR] [JOBS]   (default build/, 2 jobs)
# The points are kept in experiments/scaling/results/points/ (a point is done when its JSON is
# there), so running it again resumes; delete that folder to recompute everything.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
JOBS=2
study_args "$@"
start=$(date +%s)
study_dirs scaling
scenes=(paper-image1 paper-image2 cones-and-patches facing-mirrors)
ref() { # SCENE: the renderer's image (the golden one) and T(1), the one-processor run's time
  "$build/torusrt-render" "$root/scenes/$1.nff" -o "$work/$1.png" -q
  "$build/torusrt-sim" "$root/scenes/$1.nff" -o "$work/$1.t1.png" --stats "$work/$TAG.part.json" -q
  cmp -s "$work/$1.png" "$work/$1.t1.png" || { echo "scaling: $1: the one-processor image differs" >&2; exit 1; }
  jq -r .sim_time_s "$work/$TAG.part.json" | write_file "$work/$1.t1"
  mv -f "$work/$TAG.part.json" "$work/$TAG.json"
}
point() { # SCENE MACHINE NODES_SHAPE M DATA MAP REPLICATE [QUEUE_ORDER]
  local tag=$TAG extra=()
  [ "$7" = 0 ] || extra=(--replicate "$7" --replica-choice hash)
  "$build/torusrt-sim" "$root/scenes/$1.nff" -o "$work/$tag.png" --stats "$work/$tag.part.json" -q \
    --ips "$3" --cluster "$4" --data "$5" --map "$6" "${extra[@]}" --queue-order "${8:-primaries-first}" \
    --t1 "$(cat "$work/$1.t1")"
  cmp -s "$work/$tag.png" "$work/$1.png" && same=1 || same=0
  jq -r --arg sc "$1" --arg mc "$2" --arg m "$4" --arg d "$5" --arg map "$6" --arg r "$7" --arg same "$same" \
    '[$sc, $mc, .config.processors, .config.nodes, $m, $d, $map, $r, .sim_time_s, .t1_s, .efficiency,
      .memory.total_bytes, .memory.max_per_ip_bytes, .load.busy_s.max, .load.busy_s.mean,
      .links.utilisation.max, .packet_hops, .replication.copies, .replication.bytes,
      (.packets.conserved | tostring), $same] | @tsv' "$work/$tag.part.json" | write_file "$work/$tag.tsv"
  jq -r '.per_ip[] | [.node, .busy_s] | @tsv' "$work/$tag.part.json" | write_file "$work/$tag.busy"
  rm -f "$work/$tag.png"
  mv -f "$work/$tag.part.json" "$work/$tag.json"
}
study_script "$work" "ref point" "build root work"
# The calibrated reading's image 1 (its flakes in one plane at full size), under the default
# timing, at 512 IPs: cyclic, cost and scatter under rays-first.
planar=paper-image1-planar
printf 'ref\t%s\n' "${scenes[@]}" "$planar" | study_list "$work" "$work/phase1.list"
declare -A NODES=([4]=2x2x1 [8]=2x2x2 [16]=4x2x2 [32]=4x4x2 [64]=4x4x4 [128]=8x4x4 [256]=8x8x4
                  [512]=8x8x8 [1024]=16x8x8 [4096]=16x16x16)
{ for sc in "${scenes[@]}"; do for n in 16 64 512 4096; do
  s=${NODES[$n]}
  printf 'point\t%s\t%s\t%s\t1\treplicated\t%s\t%s\n' "$sc" flat-cyclic "$s" cyclic 0 "$sc" flat-cost "$s" cost 0 \
    "$sc" flat-cost-r0.5 "$s" cost 0.5 "$sc" flat-cost-r1.0 "$s" cost 1.0 \
    "$sc" flat-scatter "$s" scatter 0 "$sc" flat-scatter-r0.5 "$s" scatter 0.5
  printf 'point\t%s\t%s\t%s\t1\treplicated\t%s\t%s\trays-first\n' "$sc" flat-cyclic-rf "$s" cyclic 0 \
    "$sc" flat-scatter-rf "$s" scatter 0 "$sc" flat-scatter-r0.5-rf "$s" scatter 0.5
  for m in 4 16 64; do
    [ $((n / m)) -ge 4 ] || continue
    for d in replicated shared; do for map in cyclic cost; do
      printf 'point\t%s\tm%s-%s-%s\t%s\t%s\t%s\t%s\t0\n' "$sc" "$m" "$d" "$map" "${NODES[$((n / m))]}" "$m" "$d" "$map"
    done; done
  done
done; done
printf 'point\t%s\t%s\t8x8x8\t1\treplicated\t%s\t0\t%s\n' "$planar" flat-cyclic cyclic primaries-first \
  "$planar" flat-cost cost primaries-first "$planar" flat-scatter-rf scatter rays-first; } | write_file "$work/phase2.args"
study_list "$work" "$work/phase2.list" < "$work/phase2.args"
echo "scaling study: $(cat "$work"/phase[12].list | wc -l) runs on the $BACKEND backend" >&2
run_points "$work/run" scaling "$work/phase1.list" "$work/phase2.list"
header() {
  printf 'scene\tmachine\tn\tnodes\tm\tdata\tmapping\treplicate\tsim_time_s\tt1_s\tefficiency\tmemory_total_bytes'
  printf '\tmemory_max_per_ip_bytes\tbusy_max_s\tbusy_mean_s\tlink_util_max\tpacket_hops\tcopies\tcopy_bytes'
  printf '\tconserved\timage_identical\n'
}
study_rows "$work/phase2.list" tsv | sort -t$'\t' -k1,1 -k3,3n -k2,2 | write_file "$work/rows.tsv"
{ header; awk -F'\t' -v p="$planar" '$1 != p' "$work/rows.tsv"; } | write_file "$res/runs.tsv"
{ header; awk -F'\t' -v p="$planar" '$1 == p' "$work/rows.tsv"; } | write_file "$res/planar-512.tsv"
# Busy time per node, paper-image2 at 512 IPs: cost and scatter, without and with copies.
for mc in flat-cost flat-cost-r0.5 flat-cost-r1.0 flat-scatter flat-scatter-r0.5; do
  map=${mc#flat-}; map=${map%%-*}; r=${mc#flat-"$map"}; r=${r#-r}
  sed 's/^/'"$mc"'\t/' "$work/point_paper-image2_${mc}_8x8x8_1_replicated_${map}_${r:-0}.busy"
done | write_file "$res/busy-paper-image2-512.tsv"
# The share of busy IPs over time, paper-image1 at 512 IPs under the scatter, both queue orders
# (from a VCD trace of each; the traces are not kept).
for order in primaries-first rays-first; do
  "$build/torusrt-sim" "$root/scenes/paper-image1.nff" -o "$work/share.png" -q --ips 8x8x8 --map scatter \
    --queue-order "$order" --t1 "$(cat "$work/paper-image1.t1")" --vcd "$work/share.vcd"
  (cd "$root/experiments" && python3 -m report.busy_share "$work/share.vcd" 40 "$order")
  rm -f "$work/share.vcd" "$work/share.gtkw" "$work/share.png"
done | write_file "$res/busy-share-paper-image1-512.tsv"
python3 "$here/report.py" "$res" "$root/docs/scaling.md" "$pics" "$here" "$JOBS" "$(study_elapsed "$work" "$start")"
