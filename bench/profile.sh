#!/usr/bin/env bash
# Benchmark (not a test): where a simulation's CPU time goes, by perf's samples, approximately
# timed and loosely timed at several quanta. paper-image1-planar and paper-image2 at 432x432 on
# 16 and 64 IPs (a run takes a second or more); each line gives the share of the samples in the
# SystemC kernel, the C ray-tracing kernel, the model's scheduling classes (calendar, queues,
# pools), the hardware modules, the reports and set-up, and the runtime and OS
# (bench/profile_shares.py says which functions go where).
# Usage: bash bench/profile.sh [BUILD_DIR]   (PROFILE_SIZE=WxH, PROFILE_QUANTA="1ms 10ms")
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$here/build}
size=${PROFILE_SIZE:-432x432}
quanta=${PROFILE_QUANTA:-1ms 10ms 100ms}
command -v perf >/dev/null || { echo "bench/profile.sh: needs perf (Debian linux-perf)" >&2; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for scene in paper-image1-planar paper-image2; do
  for ips in 4x2x2 4x4x4; do
    for style in at $quanta; do
      opts=(); [ "$style" = at ] || opts=(--style lt --quantum "$style")
      perf record -q -F 2000 -o "$tmp/p.data" -- "$build/torusrt-sim" "$here/scenes/$scene.nff" --size "$size" \
        --ips "$ips" --t1 1 -q -o "$tmp/s.png" --stats "$tmp/s.json" "${opts[@]}" 2>/dev/null
      perf report -i "$tmp/p.data" --no-children --sort dso,symbol --stdio -g none 2>/dev/null |
        python3 "$here/bench/profile_shares.py" "$scene $ips $style ($(jq -r '.wall_s | . * 100 | round / 100' "$tmp/s.json") s)"
    done
  done
done
