#!/usr/bin/env bash
# Benchmark (not a test): the simulator's cost per packet hop. Image 1 in its planar layout
# (paper-image1-planar) under the timing profile `calibrated` with a ring's ties on the + link (a fixed
# workload whatever the defaults, so figures of different builds compare; a build without
# --route-ties sends ties that way) at 144x144 on 24^3
# cells with 16, 64, 512 and 4096 IPs (the same work at every size), and the 512-IP run on 64^3 cells at
# 1024x1024; cyclic mapping. Per row: simulated image time, wall time of the simulation (sc_start,
# after elaboration), that of the elaboration before it (building and binding the modules: a cost
# per machine, not per hop), packet hops (link crossings), microseconds of simulation wall time
# per hop, hops per second, the ratio of the simulation's wall time to torusrt-render's on the
# same scene, grid and size, and the wall time, the CPU time (user + system) and the peak
# resident memory of the whole torusrt-sim process (/usr/bin/time -v: elaboration, the run, the
# reports and the exit; on a shared machine the CPU time is the steadier figure). A 4096-IP row shows the same work on the
# largest machine the model builds.
# The machine's speed drifts from minute to minute: BENCH_RUNS=N runs every row N times, in N
# rounds of one run of each small row (the renderer too), then N runs of each large row, and
# reports the run with the least simulation wall time and the median of the N (default 1).
# A last line gives the cost of a hop at 512 IPs over that at 16 (the same work): at best, at the
# medians, and the median of the ratios within each round.
# BENCH_BASE=DIR compares two builds in one sitting: every run of a row is made by DIR's torusrt-sim
# and then by BUILD_DIR's, so a slow spell of the machine falls on both alike; the table is
# BUILD_DIR's, and a last block gives DIR's medians, each row's change at the median and the
# median of the run-by-run changes (each build run against the base run just before it).
# Usage: bash bench/sim.sh [BUILD_DIR]   (BENCH_BIG=0 skips the 1024x1024 run)
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
scene=$here/scenes/paper-image1-planar.nff
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
trap 'echo "bench/sim.sh: line $LINENO failed (status $?)" >&2' ERR
printf '%-10s %5s %6s %10s %9s %9s %7s %7s %8s %10s %11s %11s %10s %8s\n' \
  size cells ips sim_time_s wall_s wall_med_s elab_s run_s cpu_s hops us_per_hop hops_per_s vs_render peak_MB
configs=("144x144 24 4x2x2" "144x144 24 4x4x4" "144x144 24 8x8x8" "144x144 24 16x16x16")
small=3 # rows run round by round; the rest, each a quarter of a gigabyte, after them
[ "${BENCH_BIG:-1}" = 0 ] || configs+=("1024x1024 64 8x8x8")
declare -a best walls base_walls
base=${BENCH_BASE:-}
reading=(--timing-profile calibrated)
[[ $("$build/torusrt-sim" --help) != *--route-ties* ]] || reading+=(--route-ties plus)
if [ -n "$base" ]; then
  base_reading=(--timing-profile calibrated)
  [[ $("$base/torusrt-sim" --help) != *--route-ties* ]] || base_reading+=(--route-ties plus)
fi
run_row() { # one run of row $1 (and of the renderer on its scene, size and grid)
  local i=$1 size cells ips wall
  read -r size cells ips <<<"${configs[$i]}"
  "$build/torusrt-render" "$scene" --size "$size" --cells "$cells" -o "$tmp/r.png" --stats "$tmp/render.json" -q
  if [ ! -e "$tmp/r$i.json" ] || [ "$(jq ".wall_s < $(jq .wall_s "$tmp/r$i.json")" "$tmp/render.json")" = true ]; then
    mv "$tmp/render.json" "$tmp/r$i.json"
  fi
  if [ -n "$base" ]; then  # the base's run first, then the build's: alternated run by run
    "$base/torusrt-sim" "$scene" --size "$size" --cells "$cells" --ips "$ips" "${base_reading[@]}" --t1 1 \
      -o "$tmp/b.png" --stats "$tmp/base.json" -q
    base_walls[i]="${base_walls[i]:-} $(jq .sim_wall_s "$tmp/base.json")"
  fi
  /usr/bin/time -v -o "$tmp/run-time.txt" "$build/torusrt-sim" "$scene" --size "$size" --cells "$cells" --ips "$ips" \
    "${reading[@]}" --t1 1 -o "$tmp/s.png" --stats "$tmp/run.json" -q
  wall=$(jq .sim_wall_s "$tmp/run.json")
  walls[i]="${walls[i]:-} $wall"
  if [ -z "${best[i]:-}" ] || [ "$(jq -n "$wall < ${best[i]}")" = true ]; then
    best[i]=$wall
    mv "$tmp/run.json" "$tmp/s$i.json"
    mv "$tmp/run-time.txt" "$tmp/time$i.txt"
  fi
}
# Round by round, the three small rows once a round: a slow spell of the machine falls on all of
# them alike. The 4096-IP and 1024x1024 rows run their runs after them, so no small row follows
# a run that has just freed a quarter of a gigabyte.
for _ in $(seq "${BENCH_RUNS:-1}"); do
  for ((i = 0; i < small; i++)); do run_row "$i"; done
done
for ((i = small; i < ${#configs[@]}; i++)); do
  for _ in $(seq "${BENCH_RUNS:-1}"); do run_row "$i"; done
done
for i in "${!configs[@]}"; do
  read -r size cells ips <<<"${configs[$i]}"
  rss_kb=$(awk -F': ' '/Maximum resident set size/ { print $2 }' "$tmp/time$i.txt")
  cpu_s=$(awk -F': ' '/User time|System time/ { s += $2 } END { print s }' "$tmp/time$i.txt")
  run_s=$(awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, t, ":"); s = 0; for (k = 1; k <= n; k++) s = s * 60 + t[k]; print s }' "$tmp/time$i.txt")
  median=$(tr ' ' '\n' <<<"${walls[i]}" | sed '/^$/d' | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }')
  jq -r --arg size "$size" --arg cells "$cells" --argjson rw "$(jq .wall_s "$tmp/r$i.json")" --argjson rss "$rss_kb" \
    --argjson cpu "$cpu_s" --argjson med "$median" --argjson run "$run_s" \
    '[$size, $cells, .ips, .sim_time_s, .sim_wall_s, $med, .elaboration_wall_s, $run, $cpu, .links.packets, (.sim_wall_s / .links.packets * 1e6),
      .packet_hops_per_s, (.sim_wall_s / $rw), ($rss / 1024)] | @tsv' "$tmp/s$i.json" |
    awk -F'\t' '{ printf "%-10s %5s %6d %10.5f %9.3f %9.3f %7.3f %7.2f %8.2f %10d %11.3f %11.0f %9.1fx %8.1f\n",
                  $1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14 }'
done
# The same work at 16 and 512 IPs (rows 0 and 2): the cost of a hop at 512 over that at 16.
ratio() { jq -n "($2 / $(jq .links.packets "$tmp/s2.json")) / ($1 / $(jq .links.packets "$tmp/s0.json"))"; }
med() { tr ' ' '\n' <<<"$1" | sed '/^$/d' | sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
# Per round too: both rows of a round meet the same spell of the machine, so the median of the
# rounds' ratios drifts least.
rounds=$(paste -d' ' <(tr ' ' '\n' <<<"${walls[0]}" | sed '/^$/d') <(tr ' ' '\n' <<<"${walls[2]}" | sed '/^$/d') |
  while read -r w16 w512; do ratio "$w16" "$w512"; done | tr '\n' ' ')
printf '512 vs 16 IPs, wall per hop: %.2fx at best, %.2fx at the medians, %.2fx the median of the rounds'"'"' ratios\n' \
  "$(ratio "${best[0]}" "${best[2]}")" "$(ratio "$(med "${walls[0]}")" "$(med "${walls[2]}")")" "$(med "$rounds")"
# Against BENCH_BASE: its median per row and the build's change at the median.
if [ -n "$base" ]; then
  echo "against BENCH_BASE=$base (median of its runs, alternated with this build's):"
  for i in "${!configs[@]}"; do
    read -r size cells ips <<<"${configs[$i]}"
    bm=$(med "${base_walls[i]}")
    m=$(med "${walls[i]}")
    # Each run of the build against the base's run just before it: the pair meets one spell of
    # the machine, so the median of the pairs' changes drifts less than the change at the medians.
    pairs=$(paste -d' ' <(tr ' ' '\n' <<<"${base_walls[i]}" | sed '/^$/d') <(tr ' ' '\n' <<<"${walls[i]}" | sed '/^$/d') |
      while read -r b w; do jq -n "($w / $b - 1) * 100"; done | tr '\n' ' ')
    printf '%-10s %5s %8s  base %9.3f  build %9.3f  change %+6.1f %%  paired %+6.1f %%\n' "$size" "$cells" "$ips" \
      "$bm" "$m" "$(jq -n "($m / $bm - 1) * 100")" "$(med "$pairs")"
  done
fi
