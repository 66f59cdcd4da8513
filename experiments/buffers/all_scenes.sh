#!/usr/bin/env bash
# The whole cross product behind the flow-control claim, too long for CTest (cli.flow_control
# samples it): every scene in scenes/ x --queue 1, 2, 4, 8 x 8, 16, 64 processors x flat and
# clusters of 2 x AT and LT (--quantum 1ms), at 24x24 under --flow classes. Each run must exit
# 0 with torusrt-render's PNG byte for byte, conserve packets, and keep every class buffer at or
# below its capacity. Prints one line per failure and a total; exit status 1 if any failed.
# Usage: experiments/buffers/all_scenes.sh [-j JOBS] [BUILD_DIR]
set -euo pipefail
jobs=$(nproc)
if [ "${1:-}" = -j ]; then
  [[ ${2:-} =~ ^[1-9][0-9]{0,8}$ ]] || { echo "all_scenes: -j must be a whole number of runs in flight, 1 or more, not '${2:-}'" >&2; exit 2; }
  jobs=$2; shift 2
fi
REPO=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=$(cd "${1:-$REPO/build}" && pwd)
for exe in torusrt-sim torusrt-render; do
  [ -x "$BUILD/$exe" ] || { echo "all_scenes: $BUILD/$exe not found: build it first" >&2; exit 2; }
done
for tool in parallel jq cmp; do
  command -v "$tool" >/dev/null || { echo "all_scenes: needs $tool" >&2; exit 2; }
done
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
export BUILD work

for f in "$REPO"/scenes/*.nff; do
  "$BUILD/torusrt-render" "$f" -o "$work/$(basename "$f" .nff).ref.png" -q --size 24x24
done

# point SCENE QUEUE IPS CLUSTER STYLE: one run, "ok" or the reason it failed.
point() {
  local scene=$1 q=$2 ips=$3 cl=$4 style=$5 name rc=0 lt=()
  name=$(basename "$scene" .nff)
  local tag="$name-q$q-$ips-c$cl-$style"
  [ "$style" = lt ] && lt=(--quantum 1ms)
  "$BUILD/torusrt-sim" "$scene" -o "$work/$tag.png" --stats "$work/$tag.json" -q --t1 1 \
    --size 24x24 --queue "$q" --ips "$ips" --cluster "$cl" --style "$style" "${lt[@]}" 2>"$work/$tag.err" || rc=$?
  if [ "$rc" -ne 0 ]; then echo "FAIL $tag: exit $rc: $(head -n 1 "$work/$tag.err")"; return 0; fi
  cmp -s "$work/$tag.png" "$work/$name.ref.png" || { echo "FAIL $tag: image differs from torusrt-render's"; return 0; }
  jq -e '.packets.conserved and (.flow.capacity_packets as $c |
         all(.queues[]; .capacity == $c and .high_water <= $c))' "$work/$tag.json" >/dev/null ||
    { echo "FAIL $tag: packets not conserved or a buffer above its capacity"; return 0; }
  rm -f "$work/$tag.png" "$work/$tag.json" "$work/$tag.err"
  echo "ok $tag"
}
export -f point

for f in "$REPO"/scenes/*.nff; do
  for q in 1 2 4 8; do
    for m in "2x2x2 1" "4x2x2 1" "4x4x4 1" "2x2x1 2" "2x2x2 2" "4x4x2 2"; do
      for style in at lt; do printf '%s\t%s\t%s\t%s\t%s\n' "$f" "$q" "${m% *}" "${m#* }" "$style"; done
    done
  done
done > "$work/points"
start=$(date +%s)
points=$(wc -l <"$work/points")
[ "$jobs" -le "$points" ] || jobs=$points  # no more runs in flight than there are runs
parallel -j "$jobs" --colsep '\t' point {1} {2} {3} {4} {5} :::: "$work/points" > "$work/results"
grep -v '^ok ' "$work/results" || true
total=$(wc -l < "$work/results"); ok=$(grep -c '^ok ' "$work/results" || true)
echo "all_scenes: $ok of $total runs ok ($(ls "$REPO"/scenes/*.nff | wc -l) scenes x 4 capacities x 6 machines x 2 styles), $(( $(date +%s) - start )) s on $jobs job(s)"
[ "$ok" = "$total" ]
