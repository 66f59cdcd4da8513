#!/usr/bin/env bash
# collect.sh - turn a sweep's JSON reports into one CSV per figure.
#
#   experiments/collect.sh RESULTS_DIR
#
# Reads RESULTS/points.tsv (written by sweep.sh: every point the sweep should have) and each
# point's JSON, and writes in RESULTS:
#   fig5_6.csv    image time and both efficiencies against IP count, per scene and mapping
#   fig7.csv      data memory requirement against IP count, with the pixel-partitioned figure
#   fig8.csv      preprocessing units against IP count (block-mapping runs; the paper's numbers)
#   fig10_12.csv  16 clusters: image time, efficiencies, data memory, bus use against m
# A point without a JSON is still a row, with status "failed" (its .log exists) or "missing",
# and empty figures: nothing is dropped silently. Rows are sorted by scene, mapping/data, n/m.
# Also checks that every image equals the one-processor image byte for byte (image_identical).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
[ $# -eq 1 ] || die "usage: collect.sh RESULTS_DIR"
RES=$(cd "$1" && pwd)
[ -s "$RES/points.tsv" ] || die "$RES/points.tsv missing (run sweep.sh, or points.sh --tsv MODE DIR > DIR/points.tsv)"

# One row per point: the point's description, its status, then the figures from its JSON.
JQ='[.sim_time_s, .t1_s, .ips, .efficiency_t1, .efficiency_busy,
     (.memory.max_per_ip_bytes // .memory.max_per_processor_bytes // ""),
     .memory.total_bytes, .memory.pixel_partitioned_bytes, .memory.whole_scene_bytes,
     .memory.ratio_to_pixel_partitioned, .preprocess.units_serial, .preprocess.units_parallel,
     .packets.created.total, .packets.forwarded, .packets.conserved, .links.packets,
     .links.utilisation.mean, (.bus.utilisation.mean // ""), (.bus.utilisation.max // ""),
     (.bus.grant_wait_us.mean // ""), (.bus.object_reads // ""), .load.busy_s.max, .load.busy_s.mean, .wall_s,
     (.memory.shared_cell_list_bytes // ""), (.bus.object_bytes // ""), (.bus.packet_transfers // ""),
     .config.timing.bus_cycle, .config.timing.bus_width_bytes] | @tsv'
all=$RES/all.tsv
: >"$all"
while IFS=$'\t' read -r fig name scene map n shape m data json _; do
    dir=$(dirname "$json")
    if [ -s "$json" ]; then
        status=ok
        fields=$(jq -r "$JQ" "$json")
        ref=$RES/t1/$scene.png
        if [ -s "$ref" ] && cmp -s "$ref" "$dir/$name.png"; then same=yes; else same=no; fi
    else
        if [ -s "$dir/$name.log" ]; then status=failed; else status=missing; fi
        fields=$(printf '\t%.0s' {1..28})
        same=""
    fi
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$fig" "$name" "$scene" "$map" "$n" "$shape" "$m" "$data" \
        "$status" "$same" "$fields" >>"$all"
done <"$RES/points.tsv"
# Columns of all.tsv: 1 fig 2 name 3 scene 4 mapping 5 n 6 shape 7 m 8 data 9 status 10 same
# 11 T 12 T1 13 ips 14 eff_t1 15 eff_busy 16 mem_max 17 mem_total 18 mem_pp 19 whole 20 ratio
# 21 units_serial 22 units_parallel 23 created 24 forwarded 25 conserved 26 link_packets
# 27 link_util 28 bus_util 29 bus_util_max 30 bus_wait_us 31 bus_object_reads 32 busy_max 33 busy_mean 34 wall_s
# 35 cell_list_bytes (per processor, clusters) 36 bus_object_bytes 37 bus_packet_transfers 38 bus_cycle_us
# 39 bus_width_bytes

# sorted_csv HEADER SORTKEYS AWK-PROGRAM OUT
sorted_csv() {
    { echo "$1"; awk -F'\t' -v OFS=, "$3" "$all" | sort -t, $2; } >"$4.tmp"
    mv "$4.tmp" "$4"
}
sorted_csv 'scene,mapping,n,torus,status,sim_time_s,t1_s,speedup,efficiency_t1,efficiency_busy,busy_max_s,busy_mean_s,packets_created,packets_forwarded,packets_conserved,link_packets,link_util_mean,image_identical,wall_s' \
    '-k1,1 -k2,2 -k3,3n' \
    '$1 == "fig5_6" { sp = ($9 == "ok" && $11 > 0) ? $12 / $11 : "";
        print $3, $4, $5, $6, $9, $11, $12, sp, $14, $15, $32, $33, $23, $24, $25, $26, $27, $10, $34 }' \
    "$RES/fig5_6.csv"
sorted_csv 'scene,mapping,n,status,max_per_ip_bytes,total_bytes,pixel_partitioned_bytes,whole_scene_bytes,ratio_to_pixel_partitioned,pixel_partitioned_over_total' \
    '-k1,1 -k2,2 -k3,3n' \
    '$1 == "fig5_6" { inv = ($9 == "ok" && $17 > 0) ? $18 / $17 : "";
        print $3, $4, $5, $9, $16, $17, $18, $19, $20, inv }' \
    "$RES/fig7.csv"
sorted_csv 'scene,n,status,units_serial,units_parallel,speedup,paper_units,paper_speedup' \
    '-k1,1 -k2,2n' \
    'BEGIN { paper[1] = 9438; paper[16] = 738; paper[32] = 432 }
     $1 == "fig5_6" && $4 == "block" { sp = ($9 == "ok" && $22 > 0) ? $21 / $22 : "";
        pu = ($3 == "image1" && ($5 in paper)) ? paper[$5] : "";
        psp = pu != "" ? paper[1] / pu : "";
        print $3, $5, $9, $21, $22, sp, pu, psp }' \
    "$RES/fig8.csv"
sorted_csv 'scene,data,m,processors,torus,status,sim_time_s,t1_s,speedup,efficiency_t1,efficiency_busy,max_per_processor_bytes,total_bytes,pixel_partitioned_bytes,ratio_to_pixel_partitioned,bus_util_mean,bus_util_max,bus_wait_mean_us,bus_object_reads,image_identical,wall_s,paper_time_s,cell_list_bytes_per_processor,bus_object_bytes,bus_packet_transfers,bus_cycle_us,bus_width_bytes' \
    '-k1,1 -k2,2 -k3,3n' \
    'BEGIN { p["image1 replicated"] = 0.62; p["image2 replicated"] = 1.34; p["image1 shared"] = 0.75; p["image2 shared"] = 1.67 }
     $1 == "fig10_12" { sp = ($9 == "ok" && $11 > 0) ? $12 / $11 : "";
        pt = ($7 == 64 && (($3 " " $8) in p)) ? p[$3 " " $8] : "";
        print $3, $8, $7, $5, $6, $9, $11, $12, sp, $14, $15, $16, $17, $18, $20, $28, $29, $30, $31, $10, $34, pt, $35, $36, $37, $38, $39 }' \
    "$RES/fig10_12.csv"

bad=$(awk -F'\t' '$9 != "ok"' "$all" | wc -l)
diff=$(awk -F'\t' '$9 == "ok" && $10 != "yes"' "$all" | wc -l)
echo "collect: $(wc -l <"$all") points, $bad not ok, $diff images differing from the 1-processor image -> $RES/fig*.csv"
