#!/usr/bin/env bash
# styles.sh - simulation speed of the two timing styles: approximately timed (AT) and loosely
# timed (LT) at a few global quanta, on both paper scenes at 16 (4x2x2) and 64 (4x4x4) IPs.
# Prints a table of wall seconds, events per second and packet hops per second (per second of
# simulation, sim_wall_s), the speed-up over AT and the error of the image time against AT. The
# default size, 432x432, is one where a run takes a second or more.
#
# Usage: bench/styles.sh [--build DIR] [--reps N] [--quanta "0 10ms 100ms 1s"] [--size WxH]
#                        [--scenes "paper-image1 paper-image2"] [--ips "4x2x2 4x4x4"] [--csv FILE]
#   --build DIR  folder with torusrt-sim (default $TORUSRT_BUILD, else REPO/build)
#   --reps N     runs per point; the table shows the fastest (default 3; other load only adds time)
#   --csv FILE   also write the rows as CSV
# Events are packet steps + link hops + primary-ray injections (the report's "events").
set -euo pipefail
REPO=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${TORUSRT_BUILD:-$REPO/build}
REPS=3
QUANTA="0 10ms 100ms 1s"
SIZE=432x432
SCENES="paper-image1 paper-image2"
IPS="4x2x2 4x4x4"
CSV=""
die() { echo "styles.sh: $*" >&2; exit 2; }
while [ $# -gt 0 ]; do
  case $1 in
    --build) BUILD=$2; shift 2 ;;
    --reps) REPS=$2; shift 2 ;;
    --quanta) QUANTA=$2; shift 2 ;;
    --size) SIZE=$2; shift 2 ;;
    --scenes) SCENES=$2; shift 2 ;;
    --ips) IPS=$2; shift 2 ;;
    --csv) CSV=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown option $1 (see --help)" ;;
  esac
done
[[ $REPS =~ ^[1-9][0-9]*$ ]] || die "--reps: a positive integer"
SIM=$BUILD/torusrt-sim
[ -x "$SIM" ] || die "no $SIM (build it, or pass --build DIR)"
command -v jq >/dev/null || die "jq is needed"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

fastest() { printf '%s\n' "$@" | sort -g | head -n 1; }

# point STYLE QUANTUM -> sets P_WALL P_SIMWALL P_EVENTS P_HOPS P_TIME (the fastest walls)
point() {
  local style=$1 q=$2 walls=() simwalls=() r extra=()
  [ "$style" = lt ] && extra=(--quantum "$q")
  for ((r = 0; r < REPS; r++)); do
    "$SIM" "$F" -o "$TMP/o.png" --stats "$TMP/o.json" -q --size "$SIZE" --ips "$ips" --t1 "$T1" \
      --style "$style" "${extra[@]}" || die "torusrt-sim failed: $F --ips $ips --style $style ${extra[*]}"
    walls+=("$(jq -r .wall_s "$TMP/o.json")")
    simwalls+=("$(jq -r .sim_wall_s "$TMP/o.json")")
  done
  P_WALL=$(fastest "${walls[@]}")
  P_SIMWALL=$(fastest "${simwalls[@]}")
  P_EVENTS=$(jq -r .events "$TMP/o.json")
  P_HOPS=$(jq -r .packet_hops "$TMP/o.json")
  P_TIME=$(jq -r .sim_time_s "$TMP/o.json")
}

rows=$TMP/rows.csv
echo "scene,ips,style,quantum,wall_s,sim_wall_s,events,events_per_s,packet_hops,packet_hops_per_s,speedup,sim_time_s,err_time_pct" > "$rows"
for s in $SCENES; do
  F=$s
  [ -f "$F" ] || F=$REPO/scenes/$s.nff
  [ -f "$F" ] || die "no scene $s"
  for ips in $IPS; do
    "$SIM" "$F" -o "$TMP/o.png" --stats "$TMP/o.json" -q --size "$SIZE" --ips "$ips" || die "torusrt-sim failed: $F"
    T1=$(jq -r .t1_s "$TMP/o.json")
    point at ""
    at_wall=$P_WALL at_time=$P_TIME
    for spec in at $QUANTA; do
      if [ "$spec" = at ]; then style=at q=-
      else style=lt q=$spec; point lt "$q"; fi
      awk -v s="$(basename "$F" .nff)" -v i="$ips" -v st="$style" -v q="$q" -v w="$P_WALL" -v sw="$P_SIMWALL" \
          -v ev="$P_EVENTS" -v h="$P_HOPS" -v aw="$at_wall" -v t="$P_TIME" -v at="$at_time" 'BEGIN {
        printf "%s,%s,%s,%s,%.4f,%.4f,%d,%.0f,%d,%.0f,%.2f,%.6f,%.4f\n", s, i, toupper(st), q, w, sw, ev, ev / sw, h, h / sw,
               aw / w, t, 100 * (t - at) / at }' >> "$rows"
    done
    echo "styles: $(basename "$F" .nff) $ips done" >&2
  done
done
[ -n "$CSV" ] && cp "$rows" "$CSV"
echo "torusrt-sim timing styles: ${SIZE}, fastest of $REPS run(s); events/s and hops/s per second of simulation (sim_wall_s)"
awk -F, 'NR == 1 { print "scene\tIPs\tstyle\tquantum\twall s\tevents/s\tpacket-hops/s\tspeed-up\terror %"; next }
  { printf "%s\t%s\t%s\t%s\t%.3f\t%.3g\t%.3g\t%.2f\t%+.3f\n", $1, $2, $3, $4, $5, $8, $10, $11, $13 }' "$rows" | column -t -s $'\t'
