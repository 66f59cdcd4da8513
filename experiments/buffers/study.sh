#!/usr/bin/env bash
# Buffer study: image time against buffer capacity (packets per buffer of each class: 1, 2, 4,
# ..., 64 and unbounded) for both paper scenes at 16 and 64 processors, flat and with clusters of
# 2, under the deadlock-free class scheme (--flow classes) and, for comparison, one class
# (--flow none, which may deadlock); the points run on any backend (experiments/backend). Writes
# experiments/buffers/results/runs.tsv, docs/buffers.md and docs/buffers/time-vs-capacity.png.
# Usage: bash experiments/buffers/study.sh [--quick] [--results DIR] [--build DIR] [-j JOBS]
#          [--backend local|ssh:HOSTFILE|slurm] [--slurm-args "..."] [--per-task K]
#   (defaults: build/, 1 job; --quick: 32x32 pixels, capacities 1, 4 and unbounded, under a
#   minute, everything in DIR (default experiments/buffers/results-quick/), docs/ left alone)
# The points are kept in RESULTS/points/ (a point is done when its JSON is there), so running
# it again resumes; delete that folder to recompute everything.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
JOBS=1 quick=0 build=$BUILD out=
while [ $# -gt 0 ]; do
  if backend_option "$@"; then shift "$SHIFT"; continue; fi
  case $1 in
    --build|--results) need_value "$@" ;;
  esac
  case $1 in
    --quick) quick=1 ;;
    --build) build=$2; shift ;;
    --results) out=$2; shift ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) die "unknown argument '$1' (try --help)" ;;
  esac
  shift
done
set_build "$build" torusrt-render
here="$EXP/buffers"
res=${out:-$here/results$([ "$quick" = 1 ] && echo -quick)}
check_places --results --results "$res"
make_folder --results "$res"
res=$(cd "$res" && pwd)  # the points' done files are absolute paths
if [ "$quick" = 1 ]; then
  size=32x32 caps=(1 4 0) doc="$res/buffers.md" pics="$res/buffers"
else
  size=128x128 caps=(1 2 4 8 16 32 64 0) doc="$REPO/docs/buffers.md" pics="$REPO/docs/buffers"
fi
work="$res/points"
mkdir -p "$work" "$pics"
# machine: label, --ips, --cluster
machines=("16 flat	4x2x2	1" "64 flat	4x4x4	1" "16 in clusters of 2	2x2x2	2" "64 in clusters of 2	4x4x2	2")
reference() { # SCENE: the renderer's image, the golden one
  "$BUILD/torusrt-render" "$REPO/scenes/$1.nff" -o "$work/$1.png" -q --size "$size" --stats "$work/$TAG.part.json"
  mv -f "$work/$TAG.part.json" "$work/$TAG.json"
}
point() { # SCENE LABEL IPS CLUSTER FLOW CAPACITY
  local tag=$TAG rc=0 same=0
  "$SIM" "$REPO/scenes/$1.nff" -o "$work/$tag.png" --stats "$work/$tag.part.json" -q --t1 1 --size "$size" \
    --ips "$3" --cluster "$4" --flow "$5" --queue "$6" 2>/dev/null || rc=$?
  if [ "$rc" -ne 0 ]; then # a deadlock (exit 3) under --flow none leaves no report
    printf '%s\t%s\t%s\t%s\t%s\t%s\t0\t\t\t\t\t\t\t\t\t\n' "$1" "$2" "$4" "$5" "$6" \
      "$([ "$rc" = 3 ] && echo deadlock || echo "failed:$rc")" | write_file "$work/$tag.tsv"
    printf '{"exit": %d}\n' "$rc" | write_file "$work/$tag.json"
    return 0
  fi
  cmp -s "$work/$tag.png" "$work/$1.png" && same=1
  jq -r --arg sc "$1" --arg m "$2" --arg cl "$4" --arg f "$5" --arg q "$6" --arg same "$same" \
    '[$sc, $m, $cl, $f, $q, "ok", $same, .sim_time_s, .config.processors, .flow.classes_used,
      .flow.buffers_per_ip_per_class, .flow.bytes_per_ip_per_class, .flow.bytes_per_ip_used,
      .flow.bytes_per_ip_bound, .flow.high_water, (.packets.conserved | tostring)] | @tsv' \
    "$work/$tag.part.json" | write_file "$work/$tag.tsv"
  rm -f "$work/$tag.png"
  mv -f "$work/$tag.part.json" "$work/$tag.json"
}
study_script "$work" "reference point" "SIM BUILD REPO work size"
printf 'reference\t%s\n' paper-image1 paper-image2 | study_list "$work" "$work/phase1.list"
for sc in paper-image1 paper-image2; do for m in "${machines[@]}"; do for f in classes none; do
  for q in "${caps[@]}"; do printf 'point\t%s\t%s\t%s\t%s\n' "$sc" "$m" "$f" "$q"; done
done; done; done | study_list "$work" "$work/phase2.list"
echo "buffer study: $(wc -l < "$work/phase2.list") runs at $size on the $BACKEND backend" >&2
start=$(date +%s)
run_points "$work/run" buffers "$work/phase1.list" "$work/phase2.list"
wall=$(( $(date +%s) - start ))
{
  printf 'scene\tmachine\tcluster\tflow\tcapacity\tstatus\timage_identical\tsim_time_s\tprocessors\tclasses_used\tbuffers_per_ip_per_class\tbytes_per_ip_per_class\tbytes_per_ip_used\tbytes_per_ip_bound\thigh_water\tconserved\n'
  study_rows "$work/phase2.list" tsv | sort -t$'\t' -k1,1 -k2,2 -k4,4 -k5,5n
} | write_file "$res/runs.tsv"
python3 "$EXP/report/buffers.py" "$res/runs.tsv" "$doc" "$pics" "$EXP/plots/buffers.gp" \
  --size "$size" --wall "$wall" --jobs "${JOBS:-$BACKEND}"
echo "wrote $doc ($wall s)" >&2
