#!/usr/bin/env bash
# --stats-interval: the CSV time series covers the image time without gap, its processors' busy
# time sums to the JSON's busy total (within the printed rounding), every share lies in [0, 1],
# a cluster adds the bus column; a bad combination exits 2 and writes nothing.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
sim="$BUILD/torusrt-sim"
scene="$SRC/scenes/paper-image1.nff"
size=(--size 24x24)

# check_series NAME CSV JSON: the series' rows against the run's JSON.
check_series() {
    local name=$1 csv=$2 js=$3
    check "$name: the series exists" test -s "$csv"
    check "$name: its header" grep -qx 'start_s,end_s,ip_busy_share,ip_busy_s,queued,in_flight,link_use_mean,link_use_max\(,bus_use_mean\)\?' <(head -1 "$csv")
    local image busy
    image=$(jq '.sim_time_s' "$js")
    busy=$(jq '[.per_ip[].busy_s] | add' "$js")
    check "$name: the rows start at 0, follow each other and end at the image time ($image s)" \
        awk -F, -v end="$image" 'NR == 2 && $1 != 0 { bad = 1 }
            NR > 2 && $1 != last { bad = 1 }
            NR > 1 { last = $2; rows++ }
            END { d = last - end; if (d < 0) d = -d; exit !(rows > 3 && !bad && d <= 1e-9 * end + 1e-12) }' "$csv"
    check "$name: the busy time sums to the JSON's busy total ($busy s)" \
        awk -F, -v want="$busy" 'NR > 1 { s += $4 } END { d = s - want; if (d < 0) d = -d; exit !(d <= 1e-9 * want) }' "$csv"
    check "$name: every share lies in [0, 1]" \
        awk -F, 'NR > 1 { for (i = 3; i <= NF; i++) if (i != 4 && i != 5 && i != 6 && ($i < 0 || $i > 1)) bad = 1 } END { exit bad }' "$csv"
    check "$name: the processors are busy in some interval and packets are in flight" \
        awk -F, 'NR > 1 && $3 > 0 && $6 > 0 { ok = 1 } END { exit !ok }' "$csv"
    check "$name: nothing is in flight after the last row" test "$(tail -1 "$csv" | cut -d, -f6)" = 0
}

sim_ok flat "$scene" "${size[@]}" --ips 2x2x2 --t1 1 -o "$TMP/a.png" --stats "$TMP/a.json" --stats-interval 20ms
check_series flat "$TMP/a.series.csv" "$TMP/a.json"
check "flat: no bus column" test "$(head -1 "$TMP/a.series.csv" | tr ',' '\n' | wc -l)" = 8
check "flat: the links are used in some interval" awk -F, 'NR > 1 && $7 > 0 && $8 >= $7 { ok = 1 } END { exit !ok }' "$TMP/a.series.csv"

sim_ok cluster "$scene" "${size[@]}" --ips 2 --cluster 2 --t1 1 -o "$TMP/c.png" --stats "$TMP/c.json" \
    --stats-interval 50ms --stats-series "$TMP/c.csv"
check_series cluster "$TMP/c.csv" "$TMP/c.json"
check "cluster: the bus column is used" awk -F, 'NR > 1 && $9 > 0 { ok = 1 } END { exit !ok }' "$TMP/c.csv"

sim_ok lt "$scene" "${size[@]}" --ips 2x2 --style lt --quantum 1ms --t1 1 -o "$TMP/l.png" --stats "$TMP/l.json" \
    --stats-interval 10ms
check_series lt "$TMP/l.series.csv" "$TMP/l.json"

bad_option --stats-series "a series without an interval" --stats-series "$TMP/bad/x.csv"
bad_option --stats-interval "an interval of 0" --stats-interval 0
bad_option --stats-interval "too many intervals" --stats-interval 1ns
rm -rf "$TMP/bad" && mkdir "$TMP/bad"
"$sim" "$scene" "${size[@]}" -q -o "$TMP/bad/a.png" --stats-interval 1ms > /dev/null 2> "$TMP/bad.stderr"
check "an interval with nowhere to write: exit 2" test $? = 2
check "it names --stats-series" grep -q -- "--stats-series" "$TMP/bad.stderr"
check "it writes nothing" test -z "$(ls "$TMP/bad")"
cp "$scene" "$TMP/bad/scene.nff"
"$sim" "$TMP/bad/scene.nff" "${size[@]}" -q -o "$TMP/bad/a.png" --stats-interval 1ms --stats-series "$TMP/bad/scene.nff" \
    > /dev/null 2> "$TMP/bad.stderr"
check "a series over the scene: exit 2" test $? = 2
check "the scene is unchanged" cmp -s "$scene" "$TMP/bad/scene.nff"
finish
