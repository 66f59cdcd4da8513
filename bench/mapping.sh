#!/usr/bin/env bash
# Benchmark (not a test): image time of --map cost against the best of block, cyclic,
# block-cyclic 2 and 3 at n = 64 (4x4x4) and 512 (8x8x8) on both paper scenes (image 1 in its
# planar layout, the benchmarks' fixed workload) under the calibrated and literal timing profiles
# (on a flat torus the default, fitted, gives calibrated's times); prints each time, the ratio best-static / cost (target 1.5x at 64, 2x at
# 512), and the pilot and Scotch wall times (preprocessing, not in the image time).
# Usage: bash bench/mapping.sh [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
printf '%-19s %-10s %4s %9s %9s %9s %9s %9s %-15s %7s %8s %9s\n' scene profile n block cyclic bc2 bc3 cost \
  best_static ratio pilot_s scotch_s
for scene in paper-image1-planar paper-image2; do
  f="$here/scenes/$scene.nff"
  "$build/torusrt-sim" "$f" -o "$tmp/t1.png" --stats "$tmp/t1.json" -q
  t1=$(jq .sim_time_s "$tmp/t1.json") # T(1) has no hand-overs: the same under both profiles
  for profile in calibrated literal; do
    for ips in 4x4x4 8x8x8; do
      declare -A t=()
      for m in block cyclic block-cyclic:2 block-cyclic:3 cost; do
        "$build/torusrt-sim" "$f" -o "$tmp/s.png" --stats "$tmp/s.json" -q --ips "$ips" --map "$m" \
          --timing-profile "$profile" --t1 "$t1"
        cmp -s "$tmp/s.png" "$tmp/t1.png" || { echo "image differs: $scene $m $ips" >&2; exit 1; }
        t[$m]=$(jq .sim_time_s "$tmp/s.json")
      done
      best=block
      for m in cyclic block-cyclic:2 block-cyclic:3; do
        awk -v a="${t[$m]}" -v b="${t[$best]}" 'BEGIN { exit !(a < b) }' && best=$m
      done
      n=$(jq .config.nodes "$tmp/s.json")
      jq -r --arg sc "$scene" --arg p "$profile" --arg n "$n" --arg b "${t[block]}" --arg c "${t[cyclic]}" \
        --arg b2 "${t[block-cyclic:2]}" --arg b3 "${t[block-cyclic:3]}" --arg best "$best" --arg tb "${t[$best]}" \
        '[$sc, $p, $n, $b, $c, $b2, $b3, .sim_time_s, $best, ($tb | tonumber) / .sim_time_s,
          .mapping.pilot_wall_s, .mapping.mapper_wall_s] | @tsv' "$tmp/s.json" |
        awk -F'\t' '{ printf "%-19s %-10s %4d %9.3f %9.3f %9.3f %9.3f %9.3f %-15s %6.2fx %8.3f %9.3f\n",
                       $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12 }'
      unset t
    done
  done
done
