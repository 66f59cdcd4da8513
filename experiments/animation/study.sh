#!/usr/bin/env bash
# Animation study: a full orbit (360 degrees over 32 frames) of paper-image2 and paper-image1 at
# 64 and 512 nodes under six mapping policies - cyclic (static), cost (static), cost +
# every-frame remapping, cost + adaptive remapping, cost + adaptive remapping judged on the
# host's preview of each frame (--remap-pilot) and oracle - and every policy but the preview
# again over the same orbit in 128 and in 256 frames (the view turns a quarter and an eighth as
# far from one frame to the next), run on any backend (experiments/backend); every frame is
# compared with the renderer's byte for byte. Writes experiments/animation/results/ (runs.tsv, frames.tsv,
# density.tsv), docs/animation.md and docs/animation/ (the plot). Image 64x64 with 24^3 cells
# keeps the study near 40 minutes on two cores.
# Usage: bash experiments/animation/study.sh [--build DIR] [--backend local|ssh:HOSTFILE|slurm]
#          [-j JOBS] [--slurm-args "..."] [--per-task K] [BUILD_DIR] [JOBS]   (default build/, 2 jobs)
# The points are kept in experiments/animation/results/points/ (a point is done when its JSON is
# there), so running it again resumes; delete that folder to recompute everything.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
JOBS=2
study_args "$@"
study_dirs animation
frames=32 orbit=360 size=64x64
dense="256 128" # the frame counts of the finer orbits (every policy but the preview; longest first)
preview=0.015625 # the preview row's --remap-pilot: 1/64 of the pixels (8x8 of 64x64)
scenes=(paper-image2 paper-image1)
start=$(date +%s)
reference() { # SCENE FRAMES: the renderer's frames, the golden images
  mkdir -p "$work/ref-$1-$2"
  "$build/torusrt-render" "$root/scenes/$1.nff" --size "$size" --orbit "$orbit" --frames "$2" \
    -o "$work/ref-$1-$2/f_%03d.png" -q --stats "$work/$TAG.part.json"
  mv -f "$work/$TAG.part.json" "$work/$TAG.json"
}
point() { # SCENE SHAPE POLICY-NAME MAP REMAP PILOT-FRACTION (- for none) FRAMES
  local tag=$TAG dir="$work/$TAG.frames.d" pilot=()
  [ "$6" = - ] || pilot=(--remap-pilot "$6")
  rm -rf "$dir"
  mkdir -p "$dir"
  "$build/torusrt-sim" "$root/scenes/$1.nff" --size "$size" --orbit "$orbit" --frames "$7" \
    --ips "$2" --map "$4" --remap "$5" "${pilot[@]}" -o "$dir/f_%03d.png" --stats "$work/$tag.part.json" -q
  local same=1
  for f in "$work/ref-$1-$7"/*.png; do cmp -s "$f" "$dir/$(basename "$f")" || same=0; done
  if [ "$7" != "$frames" ]; then # the finer orbit: its totals only
    jq -r --arg sc "$1" --arg pol "$3" --arg same "$same" --arg fr "$7" \
      '[$sc, .config.nodes, $pol, $fr, .animation.total_s, .animation.image_time_s, .animation.migration_time_s,
        .animation.mapping_changes, (.packets.conserved | tostring), $same, .wall_s] | @tsv' \
      "$work/$tag.part.json" | write_file "$work/$tag.dense"
    rm -rf "$dir"
    mv -f "$work/$tag.part.json" "$work/$tag.json"
    return
  fi
  jq -r --arg sc "$1" --arg pol "$3" --arg same "$same" \
    '[$sc, .config.nodes, $pol, .animation.total_s, .animation.image_time_s, .animation.migration_time_s,
      .animation.migration_share, .animation.migration_bytes, .animation.mapping_changes, .animation.efficiency,
      (.packets.conserved | tostring), $same, .wall_s, .animation.host_pilot_time_s,
      .animation.host_pilot_charged_s] | @tsv' "$work/$tag.part.json" | write_file "$work/$tag.run"
  jq -r --arg sc "$1" --arg pol "$3" \
    '.config.nodes as $n | .frames[] | [$sc, $n, $pol, .index, .image_time_s, .migration_time_s,
      .migration_bytes, .efficiency, .remap.decision,
      ((.remap.reason | match("guess ([a-z-]+)").captures[0].string) // "-")] | @tsv' "$work/$tag.part.json" | write_file "$work/$tag.frames"
  rm -rf "$dir"
  mv -f "$work/$tag.part.json" "$work/$tag.json"
}
study_script "$work" "reference point" "build root work frames orbit size preview"
for sc in "${scenes[@]}"; do for n in "$frames" $dense; do printf 'reference\t%s\t%s\n' "$sc" "$n"; done; done |
  study_list "$work" "$work/phase1.list"
{
for d in $dense; do for sc in "${scenes[@]}"; do for s in 8x8x8 4x4x4; do # the longest runs first
  echo "point $sc $s adaptive cost adaptive - $d"
  echo "point $sc $s oracle cost oracle - $d"
  echo "point $sc $s every-frame cost every-frame - $d"
done; done; done
for d in $dense; do for sc in "${scenes[@]}"; do for s in 8x8x8 4x4x4; do
  echo "point $sc $s cyclic cyclic static - $d"
  echo "point $sc $s cost cost static - $d"
done; done; done
for sc in "${scenes[@]}"; do for s in 8x8x8 4x4x4; do
  echo "point $sc $s cyclic cyclic static - $frames"
  echo "point $sc $s cost cost static - $frames"
  echo "point $sc $s every-frame cost every-frame - $frames"
  echo "point $sc $s adaptive cost adaptive - $frames"
  echo "point $sc $s preview cost adaptive $preview $frames"
  echo "point $sc $s oracle cost oracle - $frames"
done; done
} | tr ' ' '\t' | study_list "$work" "$work/phase2.list"
echo "animation study: $(wc -l < "$work/phase2.list") runs of $frames and ${dense// / and } frames on the $BACKEND backend" >&2
run_points "$work/run" animation "$work/phase1.list" "$work/phase2.list"
{
  printf 'scene\tn\tpolicy\ttotal_s\timage_time_s\tmigration_time_s\tmigration_share\tmigration_bytes\tmapping_changes\tefficiency\tconserved\timages_identical\twall_s\thost_pilot_time_s\thost_pilot_charged_s\n'
  study_rows "$work/phase2.list" run | sort -t$'\t' -k1,1 -k2,2n -k3,3
} | write_file "$res/runs.tsv"
{
  printf 'scene\tn\tpolicy\tframe\timage_time_s\tmigration_time_s\tmigration_bytes\tefficiency\tdecision\tguess\n'
  study_rows "$work/phase2.list" frames | sort -t$'\t' -k1,1 -k2,2n -k3,3 -k4,4n
} | write_file "$res/frames.tsv"
{
  printf 'scene\tn\tpolicy\tframes\ttotal_s\timage_time_s\tmigration_time_s\tmapping_changes\tconserved\timages_identical\twall_s\n'
  study_rows "$work/phase2.list" dense | sort -t$'\t' -k1,1 -k2,2n -k4,4n -k3,3
} | write_file "$res/density.tsv"
elapsed=$(study_elapsed "$work" "$start")
python3 "$root/experiments/report/animation.py" "$res" "$root/docs/animation.md" "$pics" \
  "$root/experiments/plots/animation.gp" "${JOBS:-$BACKEND}" "$elapsed"
