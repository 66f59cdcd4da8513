#!/usr/bin/env bash
# Mapping study: image time and efficiency T(1)/(n T(n)) against n for block, cyclic,
# block-cyclic 2 and 3 and cost, on both paper scenes and two scenes of other load shapes,
# under both timing profiles (GNU parallel), plus load-map pictures of cyclic and cost at 64
# nodes; writes docs/mapping.md and docs/mapping/.
# Usage: bash experiments/mapping/study.sh [BUILD_DIR] [JOBS]   (default build, 2 jobs)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
jobs=${2:-2}
res="$here/results"
pics="$root/docs/mapping"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
mkdir -p "$res" "$pics"
scenes=(paper-image1 paper-image2 cones-and-patches facing-mirrors)
for sc in "${scenes[@]}"; do # T(1): no hand-overs, so the same under both profiles
  "$build/torusrt-sim" "$root/scenes/$sc.nff" -o "$work/$sc.png" --stats "$work/$sc.json" -q
  jq -r .sim_time_s "$work/$sc.json" > "$work/$sc.t1"
done
point() { # SCENE PROFILE MAP SHAPE
  local tag="$1_$2_${3//:/}_$4"
  "$build/torusrt-sim" "$root/scenes/$1.nff" -o "$work/$tag.png" --stats "$work/$tag.json" -q \
    --timing-profile "$2" --map "$3" --ips "$4" --t1 "$(cat "$work/$1.t1")"
  cmp -s "$work/$tag.png" "$work/$1.png" && same=1 || same=0
  jq -r --arg sc "$1" --arg p "$2" --arg m "$3" --arg same "$same" \
    '[$sc, $p, $m, .config.nodes, .sim_time_s, .t1_s, .efficiency, .load_balance,
      (.mapping.pilot_wall_s // 0), (.mapping.mapper_wall_s // 0), (.mapping.pilot_max_cell_work_s // 0),
      (.packets.conserved | tostring), $same] | @tsv' "$work/$tag.json" > "$work/$tag.tsv"
}
export -f point
export build root work
for sc in "${scenes[@]}"; do for p in calibrated literal; do
  for m in block cyclic block-cyclic:2 block-cyclic:3 cost; do
    for s in 2 2x2 2x2x2 4x2x2 4x4x2 4x4x4 8x4x4 8x8x4 8x8x8; do echo "$sc $p $m $s"; done
  done
done; done > "$work/points"
echo "mapping study: $(wc -l < "$work/points") runs on $jobs jobs" >&2
parallel -j "$jobs" --colsep ' ' --halt now,fail=1 point {1} {2} {3} {4} :::: "$work/points"
{
  printf 'scene\tprofile\tmapping\tn\tsim_time_s\tt1_s\tefficiency\tload_balance\tpilot_wall_s\tmapper_wall_s\tmax_cell_work_s\tconserved\timage_identical\n'
  cat "$work"/*.tsv | sort -t$'\t' -k1,1 -k2,2 -k3,3 -k4,4n
} > "$res/runs.tsv"
for sc in paper-image1 paper-image2; do
  for m in cyclic cost; do
    "$build/torusrt-sim" "$root/scenes/$sc.nff" -o "$work/lm.png" -q --ips 4x4x4 --map "$m" \
      --t1 "$(cat "$work/$sc.t1")" --load-map "$pics/load-$sc-$m.png"
  done
done
python3 "$here/report.py" "$res/runs.tsv" "$root/docs/mapping.md" "$pics" "$here"
