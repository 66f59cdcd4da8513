#!/usr/bin/env bash
# Mapping study: image time and efficiency T(1)/(n T(n)) against n for block, cyclic,
# block-cyclic 2 and 3 and cost, on both paper scenes and two scenes of other load shapes,
# under both timing profiles, on any backend (experiments/backend), plus load-map pictures of
# cyclic and cost at 64 nodes; writes docs/mapping.md and docs/mapping/.
# Usage: bash experiments/mapping/study.sh [--build DIR] [--backend local|ssh:HOSTFILE|slurm]
#          [-j JOBS] [--slurm-args "..."] [--per-task K] [BUILD_DIR] [JOBS]   (default build/, 2 jobs)
# The points are kept in experiments/mapping/results/points/ (a point is done when its JSON is
# there), so running it again resumes; delete that folder to recompute everything.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
JOBS=2
study_args "$@"
study_dirs mapping
scenes=(paper-image1 paper-image2 cones-and-patches facing-mirrors)
t1() { # SCENE; T(1): no hand-overs, so the same under both profiles
  "$build/torusrt-sim" "$root/scenes/$1.nff" -o "$work/$1.png" --stats "$work/$TAG.part.json" -q
  jq -r .sim_time_s "$work/$TAG.part.json" | write_file "$work/$1.t1"
  mv -f "$work/$TAG.part.json" "$work/$TAG.json"
}
point() { # SCENE PROFILE MAP SHAPE
  local tag=$TAG
  "$build/torusrt-sim" "$root/scenes/$1.nff" -o "$work/$tag.png" --stats "$work/$tag.part.json" -q \
    --timing-profile "$2" --map "$3" --ips "$4" --t1 "$(cat "$work/$1.t1")"
  cmp -s "$work/$tag.png" "$work/$1.png" && same=1 || same=0
  jq -r --arg sc "$1" --arg p "$2" --arg m "$3" --arg same "$same" \
    '[$sc, $p, $m, .config.nodes, .sim_time_s, .t1_s, .efficiency, .load_balance,
      (.mapping.pilot_wall_s // 0), (.mapping.mapper_wall_s // 0), (.mapping.pilot_max_cell_work_s // 0),
      (.packets.conserved | tostring), $same] | @tsv' "$work/$tag.part.json" | write_file "$work/$tag.tsv"
  rm -f "$work/$tag.png"
  mv -f "$work/$tag.part.json" "$work/$tag.json"
}
study_script "$work" "t1 point" "build root work"
printf 't1\t%s\n' "${scenes[@]}" | study_list "$work" "$work/phase1.list"
for sc in "${scenes[@]}"; do for p in fitted literal; do
  for m in block cyclic block-cyclic:2 block-cyclic:3 cost; do
    for s in 2 2x2 2x2x2 4x2x2 4x4x2 4x4x4 8x4x4 8x8x4 8x8x8; do printf 'point\t%s\t%s\t%s\t%s\n' "$sc" "$p" "$m" "$s"; done
  done
done; done | study_list "$work" "$work/phase2.list"
echo "mapping study: $(cat "$work"/phase[12].list | wc -l) runs on the $BACKEND backend" >&2
run_points "$work/run" mapping "$work/phase1.list" "$work/phase2.list"
{
  printf 'scene\tprofile\tmapping\tn\tsim_time_s\tt1_s\tefficiency\tload_balance\tpilot_wall_s\tmapper_wall_s\tmax_cell_work_s\tconserved\timage_identical\n'
  study_rows "$work/phase2.list" tsv | sort -t$'\t' -k1,1 -k2,2 -k3,3 -k4,4n
} | write_file "$res/runs.tsv"
for sc in paper-image1 paper-image2; do
  for m in cyclic cost; do
    "$build/torusrt-sim" "$root/scenes/$sc.nff" -o "$work/lm.png" -q --ips 4x4x4 --map "$m" \
      --t1 "$(cat "$work/$sc.t1")" --load-map "$pics/load-$sc-$m.png"
  done
done
python3 "$here/report.py" "$res/runs.tsv" "$root/docs/mapping.md" "$pics" "$here"
