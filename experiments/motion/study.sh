#!/usr/bin/env bash
# Motion study: the two moving scenes (scenes/bouncing-balls and scenes/orbiting-mirror with
# their motion files, 64 frames of 64x64) at 64 and 512 nodes under every remap policy - cost
# mapping kept (static), remapped before every frame (every-frame), adaptive and oracle - and
# cyclic (static) for the paper's mapping; every frame is compared with the renderer's byte for
# byte. Reports the cell-list update against a rebuild of every list, the update and its
# transfers against the render time, migration bytes, and each policy's total.
# Writes experiments/motion/results/ (runs.tsv, frames.tsv), docs/motion.md and docs/motion/
# (the per-frame plot and a strip of frames).
# Usage: bash experiments/motion/study.sh [--build DIR] [--backend local|ssh:HOSTFILE|slurm]
#          [-j JOBS] [--slurm-args "..."] [--per-task K] [BUILD_DIR] [JOBS]   (default build/, 2 jobs)
# The points are kept in experiments/motion/results/points/ (a point is done when its JSON is
# there), so running it again resumes; delete that folder to recompute everything.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
JOBS=2
study_args "$@"
start=$(date +%s)
study_dirs motion
size=64x64
scenes=(bouncing-balls orbiting-mirror)
reference() { # SCENE: the renderer's frames, the golden images
  mkdir -p "$work/ref-$1"
  "$build/torusrt-render" "$root/scenes/$1.nff" --motion "$root/scenes/$1.motion" --size "$size" \
    -o "$work/ref-$1/f_%03d.png" -q --stats "$work/$TAG.part.json"
  mv -f "$work/$TAG.part.json" "$work/$TAG.json"
}
point() { # SCENE SHAPE POLICY-NAME MAP REMAP
  local tag=$TAG dir="$work/$TAG.frames.d"
  rm -rf "$dir"
  mkdir -p "$dir"
  "$build/torusrt-sim" "$root/scenes/$1.nff" --motion "$root/scenes/$1.motion" --size "$size" \
    --ips "$2" --map "$4" --remap "$5" -o "$dir/f_%03d.png" --stats "$work/$tag.part.json" -q
  local same=1 f
  for f in "$work/ref-$1"/*.png; do cmp -s "$f" "$dir/$(basename "$f")" || same=0; done
  jq -r --arg sc "$1" --arg pol "$3" --arg same "$same" \
    '[$sc, .config.nodes, $pol, .animation.total_s, .animation.image_time_s, .animation.migration_time_s,
      .animation.migration_bytes, .animation.motion_time_s, .motion.update_time_s, .motion.link_time_s,
      .motion.bytes, .motion.update_units, .motion.rebuild_units, .animation.mapping_changes,
      (.packets.conserved | tostring), $same, .wall_s] | @tsv' "$work/$tag.part.json" | write_file "$work/$tag.run"
  jq -r --arg sc "$1" --arg pol "$3" \
    '.config.nodes as $n | .frames[] | [$sc, $n, $pol, .index, .image_time_s, .migration_time_s,
      .migration_bytes, .motion.update_time_s, .motion.link_time_s, .motion.bytes, .motion.objects_moved,
      .motion.update_units, .motion.update_units_slowest, .motion.rebuild_units, .motion.rebuild_units_slowest,
      .remap.decision, ((.remap.reason | match("guess ([a-z-]+)").captures[0].string) // "-")] | @tsv' \
    "$work/$tag.part.json" | write_file "$work/$tag.frames"
  rm -rf "$dir"
  mv -f "$work/$tag.part.json" "$work/$tag.json"
}
study_script "$work" "reference point" "build root work size"
printf 'reference\t%s\n' "${scenes[@]}" | study_list "$work" "$work/phase1.list"
for s in 8x8x8 4x4x4; do for sc in "${scenes[@]}"; do # the longest runs first
  printf 'point\t%s\t%s\t%s\t%s\t%s\n' "$sc" "$s" adaptive cost adaptive "$sc" "$s" every-frame cost every-frame \
    "$sc" "$s" oracle cost oracle "$sc" "$s" static cost static "$sc" "$s" cyclic cyclic static
done; done | study_list "$work" "$work/phase2.list"
echo "motion study: $(wc -l < "$work/phase2.list") runs of 64 frames on the $BACKEND backend" >&2
run_points "$work/run" motion "$work/phase1.list" "$work/phase2.list"
{
  printf 'scene\tn\tpolicy\ttotal_s\timage_time_s\tmigration_time_s\tmigration_bytes\tmotion_time_s'
  printf '\tupdate_time_s\tupdate_link_time_s\tupdate_bytes\tupdate_units\trebuild_units\tmapping_changes'
  printf '\tconserved\timages_identical\twall_s\n'
  study_rows "$work/phase2.list" run | sort -t$'\t' -k1,1 -k2,2n -k3,3
} | write_file "$res/runs.tsv"
{
  printf 'scene\tn\tpolicy\tframe\timage_time_s\tmigration_time_s\tmigration_bytes\tupdate_time_s'
  printf '\tupdate_link_time_s\tupdate_bytes\tobjects_moved\tupdate_units\tupdate_units_slowest'
  printf '\trebuild_units\trebuild_units_slowest\tdecision\tguess\n'
  study_rows "$work/phase2.list" frames | sort -t$'\t' -k1,1 -k2,2n -k3,3 -k4,4n
} | write_file "$res/frames.tsv"
# The strip: frames 0, 8, ..., 56 of each scene, as the renderer drew them (paths from $res).
for sc in "${scenes[@]}"; do
  for k in 0 8 16 24 32 40 48 56; do printf 'points/ref-%s/f_%03d.png\n' "$sc" "$k"; done
done | write_file "$res/strip.list"
python3 "$here/report.py" "$res" "$root/docs/motion.md" "$pics" "$here" \
  "${JOBS:-$BACKEND}" "$(study_elapsed "$work" "$start")"
