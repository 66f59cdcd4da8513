#!/usr/bin/env bash
# motion.sh - torusrt-render --motion: the shipped moving scenes render 64 frames, twice byte
# for byte and equal to the brute-force frames; a moved frame equals a plain render of the scene moved by hand; a still motion
# equals the plain render; the stats' motion keys (each frame's update no dearer than a rebuild);
# the camera stays unless --orbit moves it; every bad motion file or combination is exit 2 with
# FILE:LINE or the option, and writes no output (torusrt-sim's --motion: sim_motion.sh).
#
# Usage (CTest runs it so): bash tests/cli/motion.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-render
render="$BUILD/torusrt-render"
time_limit 300
size=(--size 24x24)

# anim_ok NAME SCENE DIR ARGS...: a --motion run writing DIR/f_%02d.png (and DIR.json) quietly.
anim_ok() {
    local name=$1 scene=$2 dir=$3
    shift 3
    mkdir -p "$dir"
    if "${run_limited[@]}" "$render" "$scene" -o "$dir/f_%02d.png" --stats "$dir.json" -q "$@" >/dev/null \
        2>"$TMP/$name.stderr" </dev/null; then
        pass
    else
        fail "$name: torusrt-render $scene $* failed: $(head -c 300 "$TMP/$name.stderr")"
    fi
}

# 1. The shipped scenes: 64 frames each (from the file), the same bytes on a second run.
for name in bouncing-balls orbiting-mirror; do
    scene=$(source_scene "$name") || exit 1
    motion="$SRC/scenes/$name.motion"
    anim_ok "$name-a" "$scene" "$TMP/$name-a" "${size[@]}" --motion "$motion"
    anim_ok "$name-b" "$scene" "$TMP/$name-b" "${size[@]}" --motion "$motion"
    check "$name: 64 frames" [ "$(ls "$TMP/$name-a" | wc -l)" -eq 64 ]
    check "$name: two runs write the same frames" diff -r "$TMP/$name-a" "$TMP/$name-b"
    # The updated cell lists lose no hit: every frame equals the brute-force frame (no grid).
    anim_ok "$name-bf" "$scene" "$TMP/$name-bf" "${size[@]}" --motion "$motion" --brute-force
    check "$name: every frame equals the brute-force frame" diff -r "$TMP/$name-a" "$TMP/$name-bf"
    check "$name: frame 1 differs from frame 0 (something moves)" \
        bash -c "! cmp -s '$TMP/$name-a/f_00.png' '$TMP/$name-a/f_01.png'"
    js="$TMP/$name-a.json"
    check "$name: frame_count 64" [ "$(json "$js" .frame_count)" = 64 ]
    check "$name: camera_source scene" [ "$(json "$js" .camera_source)" = scene ]
    check "$name: motion.file" [ "$(json "$js" .motion.file)" = "$motion" ]
    check "$name: every frame's update costs no more than a rebuild" \
        [ "$(json "$js" '[.frames[] | select(.motion.update_units > .motion.rebuild_units)] | length')" = 0 ]
    check "$name: frame 0 builds every list (update = rebuild)" \
        [ "$(json "$js" '.frames[0].motion.update_units == .frames[0].motion.rebuild_units')" = true ]
    check "$name: later frames cost less than a rebuild" \
        [ "$(json "$js" '[.frames[1:][] | select(.motion.update_units >= .motion.rebuild_units)] | length')" = 0 ]
    check "$name: the totals add the frames up" \
        [ "$(json "$js" '.motion.update_units == ([.frames[].motion.update_units] | add)')" = true ]
    check "$name: the camera stays (one pose in every frame)" \
        [ "$(json "$js" '[.frames[].camera] | unique | length')" = 1 ]
done
check "orbiting-mirror: one entry, matching one sphere" \
    [ "$(json "$TMP/orbiting-mirror-a.json" '.motion.entries[0].matched')" = \
      "$SRC/scenes/orbiting-mirror.motion:6: objects 1-1 (1 sphere), 2 keys" ]
check "orbiting-mirror: one object moves a frame" \
    [ "$(json "$TMP/orbiting-mirror-a.json" '[.frames[1:][].motion.objects_moved] | unique | tostring')" = "[1]" ]

# 2. Frame 1 of a moving sphere equals a plain render of the scene with the sphere moved there by
#    hand (the image does not depend on the grid), and frame 0 the scene as written.
cat >"$TMP/two.nff" <<'EOF'
v
from 0 0 12
at 0 0 0
up 0 1 0
angle 40
hither 0.001
resolution 24 24
b 0.1 0.1 0.2
l 5 8 10
f 0.9 0.3 0.2 0.8 0.2 20 0 1
s -2 0 0 1
f 0.2 0.6 0.9 0.8 0.2 20 0 1
s 2 0 0 1
EOF
sed 's/^s 2 0 0 1$/s 2 1.5 -1 1/' "$TMP/two.nff" >"$TMP/two-moved.nff"
printf '# sphere 1 up 1.5 and back 1 at frame 1\nframes 2\nobjects 1\nkey 0\nkey 1 move 0 1.5 -1\n' >"$TMP/two.motion"
anim_ok two "$TMP/two.nff" "$TMP/two" --motion "$TMP/two.motion"
render_ok plain "$TMP/two.nff" "$TMP/plain.png"
render_ok moved "$TMP/two-moved.nff" "$TMP/moved.png"
check "two spheres: frame 0 is the scene as written" cmp -s "$TMP/two/f_00.png" "$TMP/plain.png"
check "two spheres: frame 1 is the scene moved by hand" cmp -s "$TMP/two/f_01.png" "$TMP/moved.png"
check "two spheres: frame 1 moved one object" \
    [ "$(json "$TMP/two.json" '.frames[1].motion.objects_moved')" = 1 ]

# 3. A motion that moves nothing (turns of 0, 360 and -720 degrees): every frame is the plain image.
printf 'frames 3\nobjects 0 1\npivot 0.5 0.25 0\naxis 1 2 3\nkey 0\nkey 1 turn 360\nkey 2 turn -720\n' \
    >"$TMP/still.motion"
anim_ok still "$TMP/two.nff" "$TMP/still" --motion "$TMP/still.motion"
for k in 00 01 02; do
    check "still motion: frame $k equals the plain render" cmp -s "$TMP/still/f_$k.png" "$TMP/plain.png"
done
check "still motion: nothing moved" [ "$(json "$TMP/still.json" .motion.objects_moved)" = 0 ]

# 4. With --orbit the camera turns as well; the frame count is the motion file's.
anim_ok orbit "$TMP/two.nff" "$TMP/orbit" --motion "$TMP/two.motion" --orbit 90
check "motion + orbit: two frames" [ "$(ls "$TMP/orbit" | wc -l)" -eq 2 ]
check "motion + orbit: camera_source orbit" [ "$(json "$TMP/orbit.json" .camera_source)" = orbit ]
check "motion + orbit: frame 1 differs from the motion alone" \
    bash -c "! cmp -s '$TMP/orbit/f_01.png' '$TMP/two/f_01.png'"
check "motion + orbit: frame 0 equals the motion alone" cmp -s "$TMP/orbit/f_00.png" "$TMP/two/f_00.png"

# 5. Refused: exit 2, the file and line (or the option) on stderr, no frame and no stats.
# refused NAME WANT ARGS...: torusrt-render of two.nff with ARGS must exit 2 with WANT on stderr;
# -o is $out (a frame pattern unless set) and --stats $stats.
out= stats=
refused() {
    local name=$1 want=$2
    shift 2
    rm -rf "$TMP/bad" && mkdir "$TMP/bad"
    "${run_limited[@]}" "$render" "$TMP/two.nff" -q -o "${out:-$TMP/bad/f_%d.png}" --stats "${stats:-$TMP/bad/s.json}" "$@" \
        >/dev/null 2>"$TMP/bad.stderr" </dev/null
    local rc=$?
    check "$name: exit 2 (got $rc)" [ "$rc" = 2 ]
    check "$name: says '$want' ($(head -c 200 "$TMP/bad.stderr"))" grep -qF -- "$want" "$TMP/bad.stderr"
    check "$name: no output" [ -z "$(ls "$TMP/bad")" ]
}
printf 'frames 2\nobjects 1\nkey 0\nkey 1 scale 0\n' >"$TMP/zero.motion"
refused "scale 0" "--motion: $TMP/zero.motion:4: scale 0: must be from" --motion "$TMP/zero.motion"
printf 'frames 2\n\nobjects 1 5\nkey 0\n' >"$TMP/range.motion"
refused "objects past the scene" "--motion: $TMP/range.motion:3: objects 1-5: the scene has 2 objects" \
    --motion "$TMP/range.motion"
printf 'frames 2\nwobble\n' >"$TMP/word.motion"
refused "unknown statement" "$TMP/word.motion:2: unknown statement 'wobble'" --motion "$TMP/word.motion"
printf 'frames 2\nobjects 0\nkey 0 turn 10\n' >"$TMP/axis.motion"
refused "turn without an axis" "$TMP/axis.motion:3: key 0 turns: give the entry an 'axis X Y Z' line" \
    --motion "$TMP/axis.motion"
printf 'frames 2\nobjects 0\npivot 0 -1e30 0\nkey 0 scale 3\n' >"$TMP/far.motion" # y to 2e30
refused "moved past 1e30" "$TMP/far.motion:2: frame 0 moves object 0 past 1e30" --motion "$TMP/far.motion"
refused "no motion file" "--motion: $TMP/none.motion" --motion "$TMP/none.motion"
refused "--frames against the file" "--frames 5: $TMP/two.motion has 2 frames" --motion "$TMP/two.motion" --frames 5
printf '0 0 12  0 0 0  0 1 0  40\n' >"$TMP/one-pose.txt"
refused "--camera-path against the file" "--camera-path: $TMP/one-pose.txt holds 1 camera lines" \
    --motion "$TMP/two.motion" --camera-path "$TMP/one-pose.txt"
out="$TMP/bad/x.png" refused "a single -o" "an animation's output is a pattern" --motion "$TMP/two.motion"
stats="$TMP/two.motion" refused "the motion file as output" "--motion" --motion "$TMP/two.motion"
check "the motion file is left as it was" grep -q "^key 1 move 0 1.5 -1$" "$TMP/two.motion"

finish
