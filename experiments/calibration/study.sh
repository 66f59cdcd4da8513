#!/usr/bin/env bash
# Calibration study: which hand-over cost did the paper model? Runs both paper scenes over
# hand-over costs (send + receive) x mappings x n on the flat torus, plus the 16-cluster x 64
# machine, on any backend (experiments/backend), then writes docs/calibration.md and its plots.
# Usage: bash experiments/calibration/study.sh [--build DIR] [--backend local|ssh:HOSTFILE|slurm]
#          [-j JOBS] [--slurm-args "..."] [--per-task K] [BUILD_DIR] [JOBS]   (default build/, 2 jobs)
# The points are kept in experiments/calibration/results/points/ (a point is done when its JSON
# is there), so running it again resumes; delete that folder to recompute everything.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
JOBS=2
study_args "$@"
study_dirs calibration

costs=(0 50 340 580 1090 2180)
maps=(block cyclic block-cyclic:2 block-cyclic:3 block-cyclic:4 block-cyclic:6)
shapes=(2 2x2 2x2x2 4x2x2 4x4x2 4x4x4)
scenes=(paper-image1 paper-image2)

# A hand-over cost H is split evenly between sender and receiver; H = 2180 is the literal
# reading (creation 1600 at the sender, analysis 580 at the receiver).
for h in "${costs[@]}"; do
  if [ "$h" = 2180 ]; then s=1600 r=580; else s=$((h / 2)) r=$((h - h / 2)); fi
  printf 'handover_send %s\nhandover_receive %s\n' "$s" "$r" | write_file "$work/h$h.timing"
done

# T(1) does not depend on the hand-over cost or the mapping: one run per scene (phase 1).
t1() { # SCENE
  "$build/torusrt-sim" "$root/scenes/$1.nff" -o "$work/$1-t1.png" --stats "$work/$TAG.part.json" -q \
    --timing-profile literal
  jq -r .sim_time_s "$work/$TAG.part.json" | write_file "$work/$1.t1"
  mv -f "$work/$TAG.part.json" "$work/$TAG.json"
}

point() { # SCENE COST MAP SHAPE CLUSTER
  local sc=$1 h=$2 m=$3 ips=$4 cl=$5 tag=$TAG
  "$build/torusrt-sim" "$root/scenes/$sc.nff" -o "$work/$tag.png" --stats "$work/$tag.part.json" -q \
    --timing-profile literal --timing "$work/h$h.timing" --ips "$ips" --map "$m" --cluster "$cl" \
    --t1 "$(cat "$work/$sc.t1")" || { echo "run failed: $tag" >&2; return 1; }
  cmp -s "$work/$tag.png" "$work/$sc-t1.png" && same=1 || same=0
  jq -r --arg sc "$sc" --arg h "$h" --arg m "$m" --arg same "$same" \
    '[$sc, $h, $m, .config.processors, .config.nodes, .config.cluster, .sim_time_s, .t1_s, .efficiency_t1,
      .efficiency_busy, .packets.forwarded, (.packets.conserved | tostring), $same] | @tsv' "$work/$tag.part.json" \
    | write_file "$work/$tag.tsv"
  rm -f "$work/$tag.png"
  mv -f "$work/$tag.part.json" "$work/$tag.json"
}
study_script "$work" "t1 point" "build root work"
printf 't1\t%s\n' "${scenes[@]}" | study_list "$work" "$work/phase1.list"
{
  for sc in "${scenes[@]}"; do for h in "${costs[@]}"; do
    for m in "${maps[@]}"; do for s in "${shapes[@]}"; do printf 'point\t%s\t%s\t%s\t%s\t1\n' "$sc" "$h" "$m" "$s"; done; done
    for m in cyclic block-cyclic:2 block-cyclic:3; do printf 'point\t%s\t%s\t%s\t4x2x2\t64\n' "$sc" "$h" "$m"; done
  done; done
} | study_list "$work" "$work/phase2.list"
echo "calibration: $(cat "$work"/phase[12].list | wc -l) runs on the $BACKEND backend" >&2
run_points "$work/run" calibration "$work/phase1.list" "$work/phase2.list"

{
  printf 'scene\thandover_us\tmapping\tprocessors\tnodes\tcluster\tsim_time_s\tt1_s\tefficiency\tload_balance\tforwarded\tconserved\timage_identical\n'
  for sc in "${scenes[@]}"; do
    printf '%s\t%s\t%s\t1\t1\t1\t%s\t%s\t1\t1\t0\ttrue\t1\n' "$sc" 0 any "$(cat "$work/$sc.t1")" "$(cat "$work/$sc.t1")"
  done
  study_rows "$work/phase2.list" tsv | sort -t$'\t' -k1,1 -k2,2n -k3,3 -k6,6n -k4,4n
} | write_file "$res/runs.tsv"
python3 "$here/report.py" "$res/runs.tsv" "$root/docs/calibration.md" "$root/docs/calibration" "$here"
