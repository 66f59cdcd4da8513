#!/usr/bin/env bash
# sim_motion.sh - torusrt-sim --motion: the shipped moving scenes (their first frames) give the
# renderer's frames byte for byte on a flat torus and on clusters sharing their data, with packets
# conserved; the update's units equal the renderer's; the JSON's motion figures add up and the
# frames wait for their updates; every --remap policy gives the renderer's frames; --orbit moves
# the camera as well; a scene without objects runs; a bad motion file, --frames against the file and replicated cells are exit 2
# with no output.
#
# Usage (CTest runs it so): bash tests/cli/sim_motion.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
sim="$BUILD/torusrt-sim"
render="$BUILD/torusrt-render"
time_limit 300
size=(--size 32x32)
frames=5

# ref_ok NAME SCENE DIR ARGS...: the renderer's frames DIR/f_%d.png, quietly.
ref_ok() {
    local name=$1 scene=$2 dir=$3
    shift 3
    mkdir -p "$dir"
    if "${run_limited[@]}" "$render" "$scene" -q -o "$dir/f_%d.png" "$@" >/dev/null 2>"$TMP/$name.stderr" </dev/null
    then pass; else
        fail "$name: torusrt-render $scene $* failed: $(head -c 300 "$TMP/$name.stderr")"
        return 1
    fi
}
close() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-7 * (a < 0 ? -a : a) + 1e-12) }'; }

for name in bouncing-balls orbiting-mirror; do
    scene=$(source_scene "$name") || exit 1
    # The shipped motion over its first frames: the same keys, a shorter animation.
    motion="$TMP/$name.motion"
    sed "s/^frames 64\$/frames $frames/" "$SRC/scenes/$name.motion" >"$motion"
    check "$name: the motion file names $frames frames" grep -q "^frames $frames\$" "$motion"
    ref_ok "$name-ref" "$scene" "$TMP/$name-ref" "${size[@]}" --motion "$motion" --stats "$TMP/$name-ref.json" ||
        continue
    for named in "flat:--ips 2x2" "block:--ips 2x2x2 --map block" "shared:--ips 2x1 --cluster 2 --data shared --map cost"; do
        tag="$name-${named%%:*}"
        shape=${named#*:}
        mkdir "$TMP/$tag"
        # shellcheck disable=SC2086 # the shape is a list of options
        sim_ok "$tag" "$scene" "${size[@]}" $shape --motion "$motion" -o "$TMP/$tag/f_%d.png" \
            --stats "$TMP/$tag.json" || continue
        for ((k = 0; k < frames; k++)); do
            check "$tag: frame $k equals the renderer's" cmp -s "$TMP/$name-ref/f_$k.png" "$TMP/$tag/f_$k.png"
        done
        j="$TMP/$tag.json"
        check "$tag: conserved" [ "$(json "$j" .packets.conserved)" = true ]
        check "$tag: $frames frames" [ "$(json "$j" '.frames | length')" = "$frames" ]
        check "$tag: camera_source scene" [ "$(json "$j" .camera_source)" = scene ]
        check "$tag: frame 0 has no update" [ "$(json "$j" '.frames[0].motion.update_units')" = 0 ]
        check "$tag: every later frame's update units equal the renderer's" \
            [ "$(json "$j" '[.frames[1:][].motion.update_units]')" = \
              "$(json "$TMP/$name-ref.json" '[.frames[1:][].motion.update_units]')" ]
        check "$tag: every later frame's rebuild units equal the renderer's" \
            [ "$(json "$j" '[.frames[1:][].motion.rebuild_units]')" = \
              "$(json "$TMP/$name-ref.json" '[.frames[1:][].motion.rebuild_units]')" ]
        check "$tag: something moves and costs time" [ "$(json "$j" '.motion.time_s > 0')" = true ]
        check "$tag: the totals add the frames up" \
            [ "$(json "$j" '.motion.update_units == ([.frames[].motion.update_units] | add)')" = true ]
        check "$tag: the slowest processor has at most the update's units" \
            [ "$(json "$j" '[.frames[].motion | select(.update_units_slowest > .update_units)] | length')" = 0 ]
        check "$tag: a frame's motion time is its update plus its links" \
            [ "$(json "$j" '[.frames[].motion | select((.time_s - .update_time_s - .link_time_s) | fabs > 1e-12)] | length')" = 0 ]
        total=$(json "$j" .animation.total_s)
        parts=$(json "$j" '[.frames[].image_time_s, .frames[].migration_time_s, .frames[].motion.time_s] | add')
        check "$tag: total = images + migration + updates ($total vs $parts)" close "$total" "$parts"
        check "$tag: each frame starts after the one before and its update" \
            [ "$(json "$j" '[range(1; .frames | length) as $k | .frames[$k - 1] as $a | .frames[$k] as $b
                | select($b.start_s < $a.start_s + $a.image_time_s + $b.motion.time_s - 1e-12)] | length')" = 0 ]
    done
done
j="$TMP/orbiting-mirror-flat.json"
check "orbiting-mirror: one object moves a frame" \
    [ "$(json "$j" '[.frames[1:][].motion.objects_moved] | unique | tostring')" = "[1]" ]
check "orbiting-mirror: an update costs less than a rebuild" \
    [ "$(json "$j" '.motion.update_units < .motion.rebuild_units')" = true ]
check "bouncing-balls: moved balls change other nodes' lists (entries sent)" \
    [ "$(json "$TMP/bouncing-balls-flat.json" '.motion.entries_sent > 0 and .motion.bytes > 0')" = true ]
check "bouncing-balls, block mapping: a ball enters a node that did not hold it (a record sent)" \
    [ "$(json "$TMP/bouncing-balls-block.json" '.motion.objects_sent > 0')" = true ]

# Every --remap policy: the renderer's frames; the total adds images, migration, host pilot and
# updates; static moves no cell.
scene=$(source_scene bouncing-balls) || exit 1
for policy in static every-frame adaptive oracle; do
    tag="remap-$policy"
    mkdir "$TMP/$tag"
    sim_ok "$tag" "$scene" "${size[@]}" --ips 2x2 --map cost --motion "$TMP/bouncing-balls.motion" \
        --remap "$policy" -o "$TMP/$tag/f_%d.png" --stats "$TMP/$tag.json" || continue
    check "$tag: the renderer's frames" diff -r "$TMP/bouncing-balls-ref" "$TMP/$tag"
    j="$TMP/$tag.json"
    check "$tag: conserved" [ "$(json "$j" .packets.conserved)" = true ]
    total=$(json "$j" .animation.total_s)
    parts=$(json "$j" '[.frames[].image_time_s, .frames[].migration_time_s, .frames[].host_pilot.charged_s,
        .frames[].motion.time_s] | add')
    check "$tag: total = images + migration + host pilot + updates ($total vs $parts)" close "$total" "$parts"
    check "$tag: each frame starts after the one before, its update and its migration" \
        [ "$(json "$j" '[range(1; .frames | length) as $k | .frames[$k - 1] as $a | .frames[$k] as $b
            | select($b.start_s < $a.start_s + $a.image_time_s + $b.motion.time_s + $b.migration_time_s
                - 1e-12)] | length')" = 0 ]
done
check "remap static: no cell moves" [ "$(json "$TMP/remap-static.json" '[.frames[].migration.cells] | add')" = 0 ]
check "remap every-frame: cells move" [ "$(json "$TMP/remap-every-frame.json" '[.frames[].migration.cells] | add > 0')" = true ]

# --orbit with --motion: the frame count is the file's, the camera turns too.
scene=$(source_scene orbiting-mirror) || exit 1
motion="$TMP/orbiting-mirror.motion"
mkdir "$TMP/orbit"
ref_ok orbit-ref "$scene" "$TMP/orbit-ref" "${size[@]}" --motion "$motion" --orbit 40
if sim_ok orbit "$scene" "${size[@]}" --ips 2x2 --motion "$motion" --orbit 40 -o "$TMP/orbit/f_%d.png" \
    --stats "$TMP/orbit.json"; then
    check "motion + orbit: the renderer's frames" diff -r "$TMP/orbit-ref" "$TMP/orbit"
    check "motion + orbit: camera_source orbit" [ "$(json "$TMP/orbit.json" .camera_source)" = orbit ]
fi

# A scene without objects (only a view and lights) under a motion file of two frames: both
# executables run it, nothing moves, the frames are equal.
sed -n '/^[sp] /q;p' "$(source_scene bouncing-balls)" | grep -v '^f ' >"$TMP/empty.nff"
printf 'frames 2\n' >"$TMP/still.motion"
check "the empty scene has no object" [ "$(grep -c '^[spc] ' "$TMP/empty.nff")" = 0 ]
mkdir "$TMP/empty"
if ref_ok empty-ref "$TMP/empty.nff" "$TMP/empty-ref" "${size[@]}" --motion "$TMP/still.motion" &&
    sim_ok empty "$TMP/empty.nff" "${size[@]}" --ips 2x2 --motion "$TMP/still.motion" -o "$TMP/empty/f_%d.png" \
        --stats "$TMP/empty.json"; then
    check "empty scene: the renderer's frames" diff -r "$TMP/empty-ref" "$TMP/empty"
    check "empty scene: 2 frames, nothing moved" \
        [ "$(json "$TMP/empty.json" '[(.frames | length), .motion.objects_moved] | tostring')" = "[2,0]" ]
fi

# Refused: exit 2, the file and line or the option, no frame and no stats.
scene=$(source_scene bouncing-balls) || exit 1
printf 'frames 2\nobjects 0\nkey 0\nkey 1 scale 0\n' >"$TMP/zero.motion"
bad_option "--motion: $TMP/zero.motion:4:" "bad motion file" --motion "$TMP/zero.motion"
printf 'frames 2\nwobble\n' >"$TMP/word.motion"
bad_option "$TMP/word.motion:2: unknown statement" "unknown statement" --motion "$TMP/word.motion"
printf 'frames 2\nobjects 10 20\nkey 0\n' >"$TMP/range.motion"
bad_option "$TMP/range.motion:2: objects 10-20" "objects past the scene" --motion "$TMP/range.motion"
printf 'frames 2\nobjects 0\nkey 0\nkey 1 move 0 1 0\n' >"$TMP/two.motion"
bad_option "--frames 3" "--frames against the file" --motion "$TMP/two.motion" --frames 3
bad_option "--replicate" "replicated cells" --motion "$SRC/scenes/bouncing-balls.motion" --ips 2x2 --map cost --replicate 0.5

finish
