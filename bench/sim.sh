#!/usr/bin/env bash
# Benchmark (not a test): the simulator on both paper scenes at 1, 16 and 64 IPs (cyclic mapping):
# wall time, events/s, packet-hops/s, and the ratio of its wall time to torusrt-render's on the
# same scene. Usage: bash bench/sim.sh [BUILD_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
printf '%-14s %5s %10s %10s %14s %16s %14s\n' scene ips sim_time_s wall_s events_per_s packet_hops_per_s vs_render
for scene in paper-image1 paper-image2; do
  "$build/torusrt-render" "$here/scenes/$scene.nff" -o "$tmp/r.png" --stats "$tmp/r.json" -q
  rw=$(jq .wall_s "$tmp/r.json")
  t1=""
  for ips in 1x1x1 4x2x2 4x4x4; do
    t1flag=(); [ -n "$t1" ] && t1flag=(--t1 "$t1")
    "$build/torusrt-sim" "$here/scenes/$scene.nff" -o "$tmp/s.png" --stats "$tmp/s.json" -q --ips "$ips" "${t1flag[@]}"
    [ -z "$t1" ] && t1=$(jq .sim_time_s "$tmp/s.json")
    jq -r --arg s "$scene" --argjson rw "$rw" \
      '[$s, .ips, .sim_time_s, .sim_wall_s, .events_per_s, .packet_hops_per_s, (.sim_wall_s / $rw)] | @tsv' "$tmp/s.json" |
      awk -F'\t' '{ printf "%-14s %5d %10.3f %10.3f %14.0f %16.0f %13.1fx\n", $1, $2, $3, $4, $5, $6, $7 }'
  done
done
