#!/usr/bin/env bash
# The reproduction pipeline in quick mode (32x32, n = 1, 4, 16, m = 1, 4, 16): experiments/sweep.sh
# runs every point through GNU parallel, reports a failing point (non-zero exit, its command line,
# a "failed" row in the CSV) instead of dropping it, re-runs only what is not done, and
# collect/plot/report produce the CSVs, PNG plots and the Markdown report. On the quick data the
# directions of the paper's claims hold: cyclic load_balance >= block at 16 IPs, memory at 16
# IPs below pixel-partitioned, preprocessing units fall with P, replicated time falls with m,
# shared memory below replicated at the largest m. Every image equals the one-processor image.
# The four readings are swept, each into RESULTS/READING (fitted, the default; calibrated and
# literal, which share image 1's planar layout: their one-IP times are equal, one IP hands nothing
# over; round-one). Under fitted 16 nodes are a ring of 16 and the load-balancing points run
# cyclic; under round-one, 4x2x2 and block-cyclic:3.
# Run: bash reproduction_quick.sh BUILD_DIR SOURCE_DIR
source "$(dirname "$0")/common.bash" "$@"
EXP=$SRC/experiments
RES=$TMP/res
for tool in parallel gnuplot jq; do
    command -v $tool >/dev/null || { fail "$tool not installed"; finish; exit 1; }
done

# Builds without the cluster model say so; then figures 10-12 are left out (any other failure of
# a cluster run is a failure of this test).
clusters=(); have_clusters=1
if ! "$BUILD/torusrt-sim" "$SRC/scenes/one-pixel.nff" -o "$TMP/probe.png" --stats "$TMP/probe.json" -q --ips 2 \
        --cluster 2 >"$TMP/probe.log" 2>&1 && grep -q 'not available in this build' "$TMP/probe.log"; then
    echo "note: this build has no cluster model; figures 10-12 left out"
    clusters=(--no-clusters); have_clusters=0
fi

# 1. A sweep in which one point fails (a stand-in simulator refuses block-cyclic:2 on 16 IPs, a
#    ring of 16 under fitted, 4x2x2 under the others, while the file "fail" is there: the re-run
#    below runs the same executable, as a point made by another one would run again).
mkdir -p "$TMP/fakebuild"
touch "$TMP/fail"
cat >"$TMP/fakebuild/torusrt-sim" <<EOF
#!/usr/bin/env bash
[ ! -e "$TMP/fail" ] ||
    case " \$* " in *" --ips 4x2x2 --map block-cyclic:2 "*|*" --ips 16 --map block-cyclic:2 "*) echo "injected failure" >&2; exit 7 ;; esac
exec "$BUILD/torusrt-sim" "\$@"
EOF
chmod +x "$TMP/fakebuild/torusrt-sim"
TORUSRT_BUILD=$TMP/fakebuild bash "$EXP/sweep.sh" --quick "${clusters[@]}" --results "$RES" -j 2 \
    >"$TMP/sweep1.out" 2>"$TMP/sweep1.err"
rc=$?
check "sweep with a failing point exits non-zero (got $rc)" test "$rc" -ne 0
check "the failed point's command line is reported" grep -q 'exit 7 .*--map block-cyclic:2' "$TMP/sweep1.err"
for P in fitted calibrated literal round-one; do
    check "$P: the failed point is a 'failed' row of fig5_6.csv" \
        test "$(awk -F, '$2 == "bc2" && $3 == 16 && $6 == "failed"' "$RES/$P/fig5_6.csv" | wc -l)" -eq 2
    check "$P: the failed point's messages are kept" grep -q 'injected failure' "$RES/$P/fig5_6/image1-bc2-n16.log"
done
check "the report lists the failed points" grep -q 'bc2 mapping, n = 16: \*\*failed\*\*' "$RES/reproduction.md"

# 2. Re-run with the failure gone: only the failed points (two per reading) are computed.
rm "$TMP/fail"
start=$(date +%s)
TORUSRT_BUILD=$TMP/fakebuild bash "$EXP/sweep.sh" --quick "${clusters[@]}" --results "$RES" -j 2 >"$TMP/sweep2.out" 2>"$TMP/sweep2.err"
rc=$?
echo "quick sweep re-run: $(( $(date +%s) - start )) s"
check "re-run exits 0 (got $rc; $(tail -n 3 "$TMP/sweep2.err" | tr '\n' ' '))" test "$rc" -eq 0
check "re-run computes only the 8 missing points" test "$(tail -n 1 "$RES/runs.tsv" | cut -f7)" = 8
check "no failed points left" test ! -s "$RES/failed.tsv"

# 3. The CSVs: every expected row, all ok, identical images.
rows() { awk 'NR > 1' "$1" | wc -l; }
# not CSV COLUMN VALUE: the number of rows whose COLUMN (by header name) is not VALUE.
not() { awk -F, -v c="$2" -v want="$3" 'NR == 1 { for (i = 1; i <= NF; i++) ix[$i] = i; next } $ix[c] != want' "$1" | wc -l; }
gt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && b != "" && a + 0 > b + 0) }'; }
ge() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && b != "" && a + 0 >= b + 0) }'; }
expect10=$((have_clusters ? 6 : 0))
for P in fitted calibrated literal; do
    check "$P: fig5_6.csv has 18 rows" test "$(rows "$RES/$P/fig5_6.csv")" -eq 18
    check "$P: fig7.csv has 18 rows" test "$(rows "$RES/$P/fig7.csv")" -eq 18
    check "$P: fig8.csv has 6 rows" test "$(rows "$RES/$P/fig8.csv")" -eq 6
    check "$P: fig10_12.csv has $expect10 rows" test "$(rows "$RES/$P/fig10_12.csv")" -eq $expect10
    check "$P: fig5_6.csv header" grep -q '^scene,mapping,n,torus,timing_profile,status,sim_time_s,t1_s,speedup,efficiency,load_balance,' "$RES/$P/fig5_6.csv"
    check "$P: every point ran under its profile" test "$(not "$RES/$P/fig5_6.csv" timing_profile $P)" -eq 0
    check "$P: every fig5_6 point ok" test "$(not "$RES/$P/fig5_6.csv" status ok)" -eq 0
    check "$P: every fig10_12 point ok" test "$(not "$RES/$P/fig10_12.csv" status ok)" -eq 0
    check "$P: every flat-torus image equals the one-processor image" test "$(not "$RES/$P/fig5_6.csv" image_identical yes)" -eq 0
    check "$P: every cluster image equals the one-processor image" test "$(not "$RES/$P/fig10_12.csv" image_identical yes)" -eq 0
    check "$P: efficiency and load balance are 1 at n = 1" \
        test "$(awk -F, 'NR > 1 && $3 == 1 && ($10 != 1 || $11 != 1)' "$RES/$P/fig5_6.csv" | wc -l)" -eq 0
done
for s in image1 image2; do
    a=$(jq -r .sim_time_s "$RES/calibrated/t1/$s.json") b=$(jq -r .sim_time_s "$RES/literal/t1/$s.json")
    check "$s: one-IP time the same under calibrated and literal ($a, $b)" test "$a" = "$b"
done
a=$(awk -F, '$1 == "image1" && $2 == "cyclic" && $3 == 16 { print $7 }' "$RES/calibrated/fig5_6.csv")
b=$(awk -F, '$1 == "image1" && $2 == "cyclic" && $3 == 16 { print $7 }' "$RES/literal/fig5_6.csv")
check "image1 cyclic 16 IPs: the literal hand-over is slower ($b s) than the calibrated ($a s)" gt "$b" "$a"

# 4. Plots and report.
ispng() { [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; }
figs=(5 6 7 8)
[ $have_clusters = 1 ] && figs+=(10 11 12)
for f in "${figs[@]}"; do
    check "fig$f.png is a PNG" ispng "$RES/plots/fig$f.png"
    check "report embeds fig$f" grep -q "(img/reproduction-fig$f.png)" "$RES/reproduction.md"
    check "embedded fig$f exists" ispng "$RES/img/reproduction-fig$f.png"
done
check "report has the claims table" grep -q '^| # | claim (paper section) | paper | ours, fitted | verdict, fitted | ours, calibrated | verdict, calibrated | ours, literal | verdict, literal | ours, round-one | verdict, round-one | notes (fitted) |' "$RES/reproduction.md"
check "the fitted reading ran image 1 from paper-image1.nff" grep -q '^image1_scene,paper-image1.nff$' "$RES/fitted/run_facts.csv"
check "the fitted reading ran its 16 nodes as a ring" grep -q '^shape16,16x1x1$' "$RES/fitted/run_facts.csv"
check "round one's reading ran image 1 from paper-image1-planar-z.nff" \
    grep -q '^image1_scene,paper-image1-planar-z.nff$' "$RES/round-one/run_facts.csv"
check "round one's reading ran ties the + way" grep -q '^route_ties,plus$' "$RES/round-one/run_facts.csv"
check "the calibrated reading ran image 1 from paper-image1-planar.nff" \
    grep -q '^image1_scene,paper-image1-planar.nff$' "$RES/calibrated/run_facts.csv"
check "the fitted reading's load-balancing points ran cyclic" grep -q '^lb_map,cyclic$' "$RES/fitted/run_facts.csv"
check "round one's load-balancing points ran block-cyclic:3" grep -q '^lb_map,block-cyclic:3$' "$RES/round-one/run_facts.csv"
check "report has a row per claim" test "$(grep -c '^| [0-9][0-9]* | ' "$RES/reproduction.md")" -ge 17
check "report gives the wall time" grep -q 'wall time of the points | \*\*[0-9.]* s\*\*' "$RES/reproduction.md"

# 5. Directions of the paper's claims on the quick data (default reading).
RES=$RES/fitted
v() { awk -F, -v f="$2" -v c="$3" 'NR == 1 { for (i = 1; i <= NF; i++) ix[$i] = i; n = split(f, a, ","); next }
        { for (k = 1; k <= n; k++) { split(a[k], kv, "="); if ($ix[kv[1]] != kv[2]) next } print $ix[c]; exit }' "$1"; }
for s in image1 image2; do
    c=$(v "$RES/fig5_6.csv" "scene=$s,mapping=cyclic,n=16" load_balance)
    b=$(v "$RES/fig5_6.csv" "scene=$s,mapping=block,n=16" load_balance)
    check "$s: cyclic load_balance ($c) >= block ($b) at 16 IPs" ge "$c" "$b"
    for map in block cyclic; do
        t=$(v "$RES/fig7.csv" "scene=$s,mapping=$map,n=16" total_bytes)
        p=$(v "$RES/fig7.csv" "scene=$s,mapping=$map,n=16" pixel_partitioned_bytes)
        check "$s $map: memory at 16 IPs ($t) below pixel-partitioned ($p)" gt "$p" "$t"
    done
    u1=$(v "$RES/fig8.csv" "scene=$s,n=1" units_parallel)
    u4=$(v "$RES/fig8.csv" "scene=$s,n=4" units_parallel)
    u16=$(v "$RES/fig8.csv" "scene=$s,n=16" units_parallel)
    check "$s: preprocessing units fall with P ($u1 > $u4 > $u16)" eval 'gt "$u1" "$u4" && gt "$u4" "$u16"'
done
check "fig8 carries the paper's 9438 / 738" \
    test "$(v "$RES/fig8.csv" "scene=image1,n=1" paper_units)/$(v "$RES/fig8.csv" "scene=image1,n=16" paper_units)" = 9438/738
if [ $have_clusters = 1 ]; then
    t1=$(v "$RES/fig10_12.csv" "scene=image1,data=replicated,m=1" sim_time_s)
    t4=$(v "$RES/fig10_12.csv" "scene=image1,data=replicated,m=4" sim_time_s)
    t16=$(v "$RES/fig10_12.csv" "scene=image1,data=replicated,m=16" sim_time_s)
    check "replicated time falls with m ($t1 > $t4 > $t16)" eval 'gt "$t1" "$t4" && gt "$t4" "$t16"'
    sh=$(v "$RES/fig10_12.csv" "scene=image1,data=shared,m=16" total_bytes)
    re=$(v "$RES/fig10_12.csv" "scene=image1,data=replicated,m=16" total_bytes)
    check "shared memory ($sh) below replicated ($re) at m = 16" gt "$re" "$sh"
fi

# 6. points.sh prints one command per point; the backend's lists are JSON, tab, command.
check "points.sh prints one command per point" \
    test "$(bash "$EXP/points.sh" --build "$BUILD" "${clusters[@]}" quick "$TMP/res2" | wc -l)" -eq $((20 + expect10))
check "the phase lists are JSON<TAB>command" \
    test "$(cat "$TMP"/res/points.phase[12] | awk -F'\t' 'NF != 2 || $1 !~ /^\/.*\.json$/ || $2 !~ /run_point.sh/' | wc -l)" -eq 0
check "the phase lists hold every point of the three readings" \
    test "$(cat "$TMP"/res/points.phase[12] | wc -l)" -eq "$(cat "$TMP"/res/*/points.tsv | wc -l)"
finish
