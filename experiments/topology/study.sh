#!/usr/bin/env bash
# Topology study: the torus against the hypercube where the two are different graphs, 8x8x8
# nodes (the 9-cube) and 16x16x16 (the 12-cube), with the cyclic and the cost mapping, on both
# paper scenes and the three scenes of tests/spd_style; image time, efficiency T(1)/(n T(n)),
# link packets per packet and the busiest link, on any backend (experiments/backend); writes
# docs/topology.md.
# Usage: bash experiments/topology/study.sh [--build DIR] [--backend local|ssh:HOSTFILE|slurm]
#          [-j JOBS] [--slurm-args "..."] [--per-task K] [BUILD_DIR] [JOBS]   (default build/, 2 jobs)
# The points are kept in experiments/topology/results/points/ (a point is done when its JSON is
# there), so running it again resumes; delete that folder to recompute everything.
set -euo pipefail
source "$(dirname "$0")/../lib.sh"
JOBS=2
study_args "$@"
study_dirs topology
scenes=("$root/scenes/paper-image1.nff" "$root/scenes/paper-image2.nff" "$root/tests/spd_style/balls.nff"
        "$root/tests/spd_style/gears.nff" "$root/tests/spd_style/teapot-lid.nff")
name() { local b=${1##*/}; echo "${b%.nff}"; }
t1() { # SCENE; T(1): one processor, the same whatever the network
  local n; n=$(name "$1")
  "$build/torusrt-sim" "$1" -o "$work/$n.png" --stats "$work/$TAG.part.json" -q
  jq -r .sim_time_s "$work/$TAG.part.json" | write_file "$work/$n.t1"
  mv -f "$work/$TAG.part.json" "$work/$TAG.json"
}
point() { # SCENE TOPOLOGY MAP SHAPE
  local tag=$TAG n; n=$(name "$1")
  "$build/torusrt-sim" "$1" -o "$work/$tag.png" --stats "$work/$tag.part.json" -q \
    --topology "$2" --map "$3" --ips "$4" --t1 "$(cat "$work/$n.t1")"
  cmp -s "$work/$tag.png" "$work/$n.png" && same=1 || same=0
  jq -r --arg sc "$n" --arg t "$2" --arg m "$3" --arg s "$4" --arg same "$same" \
    '[$sc, $t, $m, $s, .config.nodes, .sim_time_s, .t1_s, .efficiency, .links.count, .links.packets,
      .packets.created.total, .links.utilisation.max, .links.utilisation.mean,
      (.packets.conserved | tostring), $same] | @tsv' "$work/$tag.part.json" | write_file "$work/$tag.tsv"
  rm -f "$work/$tag.png"
  mv -f "$work/$tag.part.json" "$work/$tag.json"
}
study_script "$work" "name t1 point" "build root work"
printf 't1\t%s\n' "${scenes[@]}" | study_list "$work" "$work/phase1.list"
for sc in "${scenes[@]}"; do for t in torus hypercube; do for m in cyclic cost; do
  for s in 8x8x8 16x16x16; do printf 'point\t%s\t%s\t%s\t%s\n' "$sc" "$t" "$m" "$s"; done
done; done; done | study_list "$work" "$work/phase2.list"
echo "topology study: $(cat "$work"/phase[12].list | wc -l) runs on the $BACKEND backend" >&2
run_points "$work/run" topology "$work/phase1.list" "$work/phase2.list"
{
  printf 'scene\ttopology\tmapping\tshape\tn\tsim_time_s\tt1_s\tefficiency\tlinks\tlink_packets\tpackets\tbusiest_link\tmean_link\tconserved\timage_identical\n'
  study_rows "$work/phase2.list" tsv | sort -t$'\t' -k1,1 -k3,3 -k4,4 -k2,2
} | write_file "$res/runs.tsv"
python3 "$here/report.py" "$res/runs.tsv" "$root/docs/topology.md"
