#!/usr/bin/env bash
# cluster_images.sh - the hierarchical system (clusters of m processors on a shared bus) renders
# exactly the reference image, and its bus statistics say what the data mode implies:
#   - on two small scenes (paper-image2 at 32x32, and a mixed scene written here), torusrt-sim's
#     PNG equals torusrt-render's for --ips 2x2x1 with --cluster 1, 2, 4, 12, 64, both --data
#     modes and both --arbiter policies (plus shortest-queue dispatch, loosely-timed runs and a
#     VCD run);
#   - replicated data moves zero object bytes over the bus, shared data moves some;
#   - with shared data the bus utilisation (mean over buses) rises from m = 2 to 4 to 8;
#   - with --cluster 1 no bus section is reported (no bus is elaborated).
# JSON values are read with awk (json_get in common.bash) from the pretty-printed report (no jq or
# python needed).
#
# Usage (CTest runs it so): bash tests/cli/cluster_images.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
sim="$BUILD/torusrt-sim"
render="$BUILD/torusrt-render"
time_limit 300

# The scene with paper-image2, from the source tree or generated.
scene2=$(source_scene paper-image2) || exit 1
# A small mixed scene: mirror, glass, polygons, a cylinder and overlapping spheres.
mixed="$TMP/mixed.nff"
cat >"$mixed" <<'NFF'
v
from 0 2 9
at 0 0 0
up 0 1 0
angle 45
hither 0.01
resolution 24 24
b 0.1 0.1 0.3
am 0.1 0.1 0.1
l 4 6 6
l -5 4 3 0.5 0.5 0.5
f 0.9 0.2 0.2 0.8 0.3 20 0 1
s -1.5 0 0 1
s -0.8 0.6 0.5 0.5
f 0.8 0.8 0.9 0.1 0.1 40 0.8 1.5
s 1.2 0 0.8 0.9
f 0.3 0.9 0.3 0.9 0 0 0 1
p 4
-4 -1 -4
-4 -1 4
4 -1 4
4 -1 -4
c
0 -1 -2 0.4
0 1.5 -2 0.4
f 0.9 0.9 0.2 0.6 0.5 10 0 1
s 2.5 1.2 -1 0.6
NFF

# run NAME SCENE SIZE ARGS... - one torusrt-sim run into $TMP/NAME.{png,json}; 0 if it succeeded.
run() {
    local name=$1 scene=$2 size=$3
    shift 3
    if ! "${run_limited[@]}" "$sim" "$scene" --size "$size" --ips 2x2x1 --t1 1 -q -o "$TMP/$name.png" \
        --stats "$TMP/$name.json" "$@" 2>"$TMP/$name.err"; then
        fail "$name: torusrt-sim $* failed: $(head -c 400 "$TMP/$name.err")"
        return 1
    fi
    return 0
}

for scene_name in paper-image2 mixed; do
    if [ "$scene_name" = mixed ]; then scene=$mixed; size=24x24; else scene=$scene2; size=32x32; fi
    ref="$TMP/$scene_name.ref.png"
    if ! "$render" "$scene" --size "$size" -q -o "$ref"; then
        fail "$scene_name: torusrt-render failed"
        continue
    fi
    for m in 1 2 4 12 64; do
        for data in replicated shared; do
            for arb in round-robin fixed-priority; do
                name="$scene_name.m$m.$data.$arb"
                run "$name" "$scene" "$size" --cluster "$m" --data "$data" --arbiter "$arb" || continue
                if cmp -s "$TMP/$name.png" "$ref"; then pass; else fail "$name: PNG differs from torusrt-render's"; fi
                obj=$(json_get "$TMP/$name.json" bus.object_bytes)
                if [ "$m" = 1 ]; then
                    if [ -z "$obj" ]; then pass; else fail "$name: --cluster 1 reports a bus"; fi
                elif [ "$data" = replicated ]; then
                    if awk -v v="$obj" 'BEGIN { exit !(v != "" && v + 0 == 0) }'; then pass
                    else fail "$name: replicated data moved object bytes over the bus ($obj)"; fi
                else
                    if awk -v v="$obj" 'BEGIN { exit !(v != "" && v + 0 > 0) }'; then pass
                    else fail "$name: shared data moved no object bytes over the bus ($obj)"; fi
                fi
            done
        done
    done
    # Other policies and timing styles must not change the image either.
    for extra in "--cluster 12 --dispatch shortest-queue --data shared" \
        "--cluster 4 --style lt --quantum 1ms --data shared" \
        "--cluster 64 --style lt --quantum 50ms --data shared --arbiter fixed-priority" \
        "--cluster 3 --style lt --dispatch shortest-queue"; do
        name="$scene_name.extra$((PASSED + FAILED))"
        # shellcheck disable=SC2086
        run "$name" "$scene" "$size" $extra || continue
        if cmp -s "$TMP/$name.png" "$ref"; then pass; else fail "$name ($extra): PNG differs"; fi
    done
done

# Shared data: the bus gets busier as m grows (paper-image2, 32x32).
prev=""
for m in 2 4 8; do
    name="util.m$m"
    run "$name" "$scene2" 32x32 --cluster "$m" --data shared || continue
    u=$(json_get "$TMP/$name.json" bus.utilisation.mean)
    echo "shared m=$m: bus utilisation mean $u"
    if [ -n "$prev" ]; then
        if awk -v a="$prev" -v b="$u" 'BEGIN { exit !(b + 0 > a + 0) }'; then pass
        else fail "shared bus utilisation did not rise to m=$m ($prev -> $u)"; fi
    fi
    prev=$u
done

# The VCD holds the bus owner and request lines.
if run vcd "$mixed" 12x12 --cluster 3 --data shared --vcd "$TMP/trace.vcd" --trace-ips 1; then
    if grep -q ' owner ' "$TMP/trace.vcd" && grep -q ' request_0 ' "$TMP/trace.vcd" &&
        grep -q ' request_cu ' "$TMP/trace.vcd" && grep -q '^\$scope module cluster_1 ' "$TMP/trace.vcd"; then
        pass
    else
        fail "VCD lacks the bus owner / request lines of cluster_1"
    fi
fi

finish
