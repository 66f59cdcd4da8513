#!/usr/bin/env bash
# pruning.sh - the shade-tree pruning study: images rendered with --max-depth 0..8 (min-weight at
# its default) and with --min-weight 1/512..1/8 (max-depth at its default), compared with the
# default-settings image of the reference renderer (max-depth 8, min-weight 1/512, "full
# depth"), against the simulated image time and the wall time of the reference renderer (one
# processor: its T(1)) and of torusrt-sim on each torus size. One extra row per scene ("beyond":
# max-depth 32, min-weight 1/65536) tells how far the defaults are from a deeper tree.
#
# Usage: pruning.sh [--build DIR] [--out CSV] [--scenes "S..."] [--ips "4x2x2 ..."] [--size WxH]
#                   [--depths "0 1 ..."] [--weights "1/512 ..."] [--reps N] [--no-beyond]
#   --build DIR   folder with torusrt-sim and torusrt-render (default $TORUSRT_BUILD, else REPO/build)
#   --out CSV     output (default experiments/error_vs_runtime/results/pruning.csv)
#   --scenes      scene names in scenes/ or NFF paths (default "paper-image1 paper-image2")
#   --ips         torus sizes for torusrt-sim, AT style (default "4x2x2 4x4x4"; "" = render only)
#   --size        image size (default 144x144)
#   --depths      max-depth values (default "0 1 2 3 4 5 6 7 8")
#   --weights     min-weight values (default "1/512 1/256 1/128 1/64 1/32 1/16 1/8")
#   --reps N      timed repetitions per point; wall times are the fastest of the N (default 3)
#
# Columns: scene, sweep (max_depth, min_weight or beyond), max_depth, min_weight, runner (render
# or sim-PXxPYxPZ), processors, image_time_s (render: t1_s; sim: sim_time_s), wall_s, sim_wall_s
# (fastest of the repetitions; render: wall_s), packets (ray and shadow packets created), psnr_db, max_abs_diff, pixels_off_gt2,
# total_pixels (against the default-settings reference image), image_equals_render (the sim's
# PNG is byte-equal to the renderer's at the same settings; always true for render rows).
set -euo pipefail
# shellcheck source=experiments/error_vs_runtime/common.sh
source "$(dirname "$0")/common.sh"

OUT=$EVR_DIR/results/pruning.csv
SCENES="paper-image1 paper-image2"
IPS="4x2x2 4x4x4"
SIZE=144x144
DEPTHS="0 1 2 3 4 5 6 7 8"
WEIGHTS="1/512 1/256 1/128 1/64 1/32 1/16 1/8"
REPS=3
BEYOND=1
DEFAULT_DEPTH=8
DEFAULT_WEIGHT=1/512
while [ $# -gt 0 ]; do
  case $1 in
    --depths|--weights) need_value "$@" ;;
  esac
  case $1 in
    --depths) DEPTHS=$2; shift 2 ;;
    --weights) WEIGHTS=$2; shift 2 ;;
    --no-beyond) BEYOND=0; shift ;;
    *) study_option "$@"; shift "$SHIFT" ;;
  esac
done
[[ $REPS =~ ^[1-9][0-9]*$ ]] || die "--reps: a positive integer"
need_build
CMP=$(png_compare_tool) || die "no png_compare tool"

csv_start "scene,sweep,max_depth,min_weight,runner,processors,image_time_s,wall_s,sim_wall_s,packets,psnr_db,max_abs_diff,pixels_off_gt2,total_pixels,image_equals_render"

for s in $SCENES; do
  F=$(scene_file "$s")
  [ -f "$F" ] || die "no scene $F"
  name=$(scene_name "$F")
  "$BUILD/torusrt-render" "$F" -o "$TMP/ref.png" -q --size "$SIZE" || die "torusrt-render failed: $F"
  settings=()
  for d in $DEPTHS; do settings+=("max_depth $d $DEFAULT_WEIGHT"); done
  for w in $WEIGHTS; do settings+=("min_weight $DEFAULT_DEPTH $w"); done
  [ "$BEYOND" = 1 ] && settings+=("beyond 32 1/65536")
  for setting in "${settings[@]}"; do
    read -r sweep d w <<<"$setting"
    timed_runs render torusrt-render --max-depth "$d" --min-weight "$w"
    read -r psnr maxd off total < <("$CMP" "$TMP/ref.png" "$TMP/render.png") || die "png_compare failed"
    t1=$(jq -r .t1_s "$TMP/render.json")
    packets=$(jq -r .packets.created.total "$TMP/render.json")
    echo "$name,$sweep,$d,$w,render,1,$t1,$M_WALL,$M_SIM_WALL,$packets,$psnr,$maxd,$off,$total,true" >> "$CSV"
    echo "pruning: $name $sweep depth $d weight $w  render PSNR $psnr dB  T(1) $t1 s" >&2
    for ips in $IPS; do
      timed_runs sim torusrt-sim --ips "$ips" --max-depth "$d" --min-weight "$w" --t1 "$t1"
      eq=false
      cmp -s "$TMP/render.png" "$TMP/sim.png" && eq=true
      read -r psnr maxd off total < <("$CMP" "$TMP/ref.png" "$TMP/sim.png") || die "png_compare failed"
      jq -r --arg name "$name" --arg sweep "$sweep" --arg d "$d" --arg w "$w" --arg ips "$ips" \
        --arg wall "$M_WALL" --arg sw "$M_SIM_WALL" --arg psnr "$psnr" --arg maxd "$maxd" --arg off "$off" \
        --arg total "$total" --arg eq "$eq" \
        '[$name, $sweep, $d, $w, "sim-" + $ips, .ips, .sim_time_s, $wall, $sw, .packets.created.total,
          $psnr, $maxd, $off, $total, $eq] | map(tostring) | join(",")' "$TMP/sim.json" >> "$CSV"
      echo "pruning: $name $sweep depth $d weight $w  sim $ips  $(jq -r .sim_time_s "$TMP/sim.json") s  equals render: $eq" >&2
    done
  done
done
csv_finish
