#!/usr/bin/env bash
# Benchmark (not a test): the reference renderer on both paper scenes (image 1 in its planar
# layout, the benchmarks' fixed workload), grid and brute force.
# Prints rays (packets) per second and wall time. Usage: bash bench/render.sh [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
printf '%-19s %-12s %10s %12s %14s\n' scene mode packets wall_s rays_per_s
for scene in paper-image1-planar paper-image2; do
  for mode in grid brute-force; do
    flag=(); [ "$mode" = brute-force ] && flag=(--brute-force)
    best=""
    for rep in 1 2 3; do   # best of three: the machine may be busy
      "$build/torusrt-render" "$here/scenes/$scene.nff" -o "$tmp/o.png" --stats "$tmp/o.json" -q "${flag[@]}"
      w=$(jq .wall_s "$tmp/o.json")
      if [ -z "$best" ] || awk -v a="$w" -v b="$best" 'BEGIN{exit !(a<b)}'; then best=$w; cp "$tmp/o.json" "$tmp/best.json"; fi
    done
    jq -r --arg s "$scene" --arg m "$mode" \
      '[$s, $m, .packets.created.total, .wall_s, (.packets.created.total / .wall_s)] | @tsv' "$tmp/best.json" |
      awk -F'\t' '{ printf "%-19s %-12s %10d %12.4f %14.0f\n", $1, $2, $3, $4, $5 }'
  done
done
