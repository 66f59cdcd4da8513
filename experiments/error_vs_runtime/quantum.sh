#!/usr/bin/env bash
# quantum.sh - the timing-style study: for each scene and torus size, one approximately-timed
# (AT) run as the reference, then loosely-timed (LT) runs at growing global quanta until the
# error of the image time passes a bound. Writes one CSV row per run configuration.
#
# Usage: quantum.sh [--build DIR] [--out CSV] [--scenes "S..."] [--ips "4x2x2 ..."] [--size WxH]
#                   [--quanta "0 10us ..."] [--max-error PCT] [--reps N]
#   --build DIR     folder with torusrt-sim (default $TORUSRT_BUILD, else REPO/build)
#   --out CSV       output (default experiments/error_vs_runtime/results/quantum.csv)
#   --scenes        scene names in scenes/ or NFF paths (default "paper-image1 paper-image2")
#   --ips           torus sizes (default "4x2x2 4x4x4 8x8x8")
#   --size          image size (default 144x144)
#   --quanta        quanta to try in order (default 0, 10us, 100us, then 1-2-5 steps from 1ms to 100s)
#   --max-error     stop a configuration after the first quantum whose |error of sim_time_s|
#                   exceeds this many per cent (default 20; the upper bound is the last quantum)
#   --reps N        timed repetitions per point; wall times are the fastest of the N (default 5)
#
# Columns: scene, ips, processors, style, quantum, quantum_s, sim_time_s, efficiency_busy,
# efficiency_t1, err_time_pct, err_eff_pct (signed, against the AT row), wall_s, sim_wall_s
# (fastest of the repetitions), speedup, speedup_sim (AT wall / this wall), events, events_per_s, packet_hops,
# packet_hops_per_s (per second of sim_wall_s), delta_cycles, image_equal (PNG byte-equal
# to AT), deterministic (every repetition gave the same sim_time_s), t1_s.
set -euo pipefail
# shellcheck source=experiments/error_vs_runtime/common.sh
source "$(dirname "$0")/common.sh"

OUT=$EVR_DIR/results/quantum.csv
SCENES="paper-image1 paper-image2"
IPS="4x2x2 4x4x4 8x8x8"
SIZE=144x144
QUANTA="0 10us 100us 1ms 2ms 5ms 10ms 20ms 50ms 100ms 200ms 500ms 1s 2s 5s 10s 20s 50s 100s"
MAX_ERR=20
REPS=5
while [ $# -gt 0 ]; do
  case $1 in
    --quanta|--max-error) need_value "$@" ;;
  esac
  case $1 in
    --quanta) QUANTA=$2; shift 2 ;;
    --max-error) MAX_ERR=$2; shift 2 ;;
    *) study_option "$@"; shift "$SHIFT" ;;
  esac
done
[[ $REPS =~ ^[1-9][0-9]*$ ]] || die "--reps: a positive integer"
# the strict decimal syntax of every torusrt format: 010, .5, inf and nan refused
[[ $MAX_ERR =~ ^(0|[1-9][0-9]*)(\.[0-9]+)?$ ]] || die "--max-error: a percentage, a decimal number 0 or more (not '$MAX_ERR')"
need_build
# quantum_seconds Q: Q in seconds, as torusrt-sim reads it (its --dump-config writes microseconds).
quantum_seconds() {
  "$BUILD/torusrt-sim" --dump-config --style lt --quantum "$1" 2>/dev/null |
    sed -n 's/^quantum="\(.*\)us"$/\1/p' | awk '{ printf "%.12g\n", $1 * 1e-6 }'
}
for q in $QUANTA; do [ -n "$(quantum_seconds "$q")" ] || die "--quanta: bad quantum '$q'"; done

csv_start "scene,ips,processors,style,quantum,quantum_s,sim_time_s,efficiency_busy,efficiency_t1,err_time_pct,err_eff_pct,wall_s,sim_wall_s,speedup,speedup_sim,events,events_per_s,packet_hops,packet_hops_per_s,delta_cycles,image_equal,deterministic,t1_s"

for s in $SCENES; do
  F=$(scene_file "$s")
  [ -f "$F" ] || die "no scene $F"
  name=$(scene_name "$F")
  for ips in $IPS; do
    n=$(ip_count "$ips")
    # A first AT run computes T(1); every timed run then gets it with --t1.
    "$BUILD/torusrt-sim" "$F" -o "$TMP/t1.png" --stats "$TMP/t1.json" -q --size "$SIZE" --ips "$ips" ||
      die "torusrt-sim failed: $F --ips $ips"
    t1=$(jq -r .t1_s "$TMP/t1.json")
    timed_runs at torusrt-sim --ips "$ips" --style at --t1 "$t1"
    at_T=$(jq -r .sim_time_s "$TMP/at.json")
    at_E=$(jq -r .efficiency_busy "$TMP/at.json")
    at_W=$M_WALL
    at_SW=$M_SIM_WALL
    row() { # row STYLE QUANTUM QUANTUM_S JSON IMAGE_EQUAL
      jq -r --arg scene "$name" --arg ips "$ips" --argjson n "$n" --arg style "$1" --arg q "$2" --arg qs "$3" \
        --arg eq "$5" --arg det "$M_DET" --arg w "$M_WALL" --arg sw "$M_SIM_WALL" \
        '[$scene, $ips, $n, $style, $q, $qs, .sim_time_s, .efficiency_busy, .efficiency_t1, "ERRT", "ERRE",
          $w, $sw, "SPD", "SPDS", .events, "EPS", .packet_hops, "HPS", .delta_cycles, $eq, $det, .t1_s] | @csv' "$4" |
        tr -d '"' |
        awk -F, -v OFS=, -v aT="$at_T" -v aE="$at_E" -v aW="$at_W" -v aSW="$at_SW" '{
          $10 = sprintf("%.6g", 100 * ($7 - aT) / aT); $11 = sprintf("%.6g", 100 * ($8 - aE) / aE)
          $14 = sprintf("%.4g", aW / $12); $15 = sprintf("%.4g", aSW / $13)
          $17 = sprintf("%.6g", $16 / $13); $19 = sprintf("%.6g", $18 / $13); print }'
    }
    row at "" 0 "$TMP/at.json" true >> "$CSV"
    echo "quantum: $name $ips AT  sim_time_s $at_T  wall $at_W s" >&2
    for q in $QUANTA; do
      qs=$(quantum_seconds "$q")
      timed_runs lt torusrt-sim --ips "$ips" --style lt --quantum "$q" --t1 "$t1"
      eq=false
      cmp -s "$TMP/at.png" "$TMP/lt.png" && eq=true
      row lt "$q" "$qs" "$TMP/lt.json" "$eq" >> "$CSV"
      err=$(tail -n 1 "$CSV" | cut -d, -f10)
      echo "quantum: $name $ips LT $q  error $err %  wall $M_WALL s  image_equal $eq" >&2
      awk -v e="$err" -v m="$MAX_ERR" 'BEGIN { exit !((e < 0 ? -e : e) > m) }' && break
    done
  done
done
csv_finish
