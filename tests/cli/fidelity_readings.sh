#!/usr/bin/env bash
# fidelity_readings.sh - the readings of the paper's unknowns (docs/fidelity.md) as settings:
# the counting rules in both executables, the scene variants against the reference renderer,
# the memory accounting, the paper's machine files with their timing file beside them, and round
# one's reading by name (machines/round-one/).
#
# Usage: bash tests/cli/fidelity_readings.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
sim=$BUILD/torusrt-sim
render=$BUILD/torusrt-render
time_limit 300
img1=$SRC/scenes/paper-image1.nff

# 1. The counting rule: both executables count the same units; the rule changes the units and
#    nothing else (the default is today's sequential count).
for rule in sequential per-plane bounding-sphere; do
    "${run_limited[@]}" "$render" "$img1" --size 8x8 --preprocess-count "$rule" -q -o "$TMP/r-$rule.png" \
        --stats "$TMP/r-$rule.json" || fail "torusrt-render --preprocess-count $rule failed"
    sim_ok "sim-$rule" "$img1" --size 8x8 --ips 4x2x2 --preprocess-count "$rule" -o "$TMP/s-$rule.png" \
        --stats "$TMP/s-$rule.json"
    check "$rule: render and sim count the same units" \
        [ "$(json "$TMP/r-$rule.json" .preprocess.units_serial)" = "$(json "$TMP/s-$rule.json" .preprocess.units_serial)" ]
    check "$rule: the image does not depend on the rule" cmp -s "$TMP/s-$rule.png" "$TMP/s-sequential.png"
done
"${run_limited[@]}" "$render" "$img1" --size 8x8 -q -o "$TMP/r-default.png" --stats "$TMP/r-default.json"
check "the default rule is sequential" \
    [ "$(json "$TMP/r-default.json" .preprocess.units_serial)" = "$(json "$TMP/r-sequential.json" .preprocess.units_serial)" ]
check "per-plane counts fewer units than sequential" \
    [ "$(json "$TMP/r-per-plane.json" .preprocess.units_serial)" -lt "$(json "$TMP/r-sequential.json" .preprocess.units_serial)" ]
check "the sim reports its rule" [ "$(json "$TMP/s-per-plane.json" '.config.options["preprocess-count"]')" = per-plane ]
"$render" "$img1" --preprocess-count sideways -o "$TMP/bad.png" 2>"$TMP/bad.err"
check "an unknown rule exits 2" [ $? -eq 2 ]
check "an unknown rule is named" grep -q -- "--preprocess-count 'sideways'" "$TMP/bad.err"
check "an unknown rule writes nothing" [ ! -e "$TMP/bad.png" ]

# 2. Every scene variant renders in the model exactly as the reference renderer renders it.
for name in paper-image1-planar paper-image1-cube paper-image1-tree paper-image2-wall; do
    f=$SRC/scenes/$name.nff
    "${run_limited[@]}" "$render" "$f" --size 24x24 -q -o "$TMP/$name-ref.png" || fail "torusrt-render $name failed"
    sim_ok "$name" "$f" --size 24x24 --ips 4x4 --map block-cyclic:2 --cluster 2 -o "$TMP/$name-sim.png" \
        --stats "$TMP/$name.json"
    check "$name: torusrt-sim's image equals torusrt-render's" cmp -s "$TMP/$name-ref.png" "$TMP/$name-sim.png"
    check "$name: packets conserved" [ "$(json "$TMP/$name.json" .packets.conserved)" = true ]
done

# 3. The memory accounting: a cell header of 0 bytes takes exactly 4 bytes per cell off the whole
#    scene; a 100-byte record charges 100 bytes per object; the defaults are 4 / 4 / natural.
sim_ok mem-default "$img1" --size 8x8 -o "$TMP/m0.png" --stats "$TMP/m0.json"
sim_ok mem-noheader "$img1" --size 8x8 --cell-header-bytes 0 -o "$TMP/m1.png" --stats "$TMP/m1.json"
sim_ok mem-record "$img1" --size 8x8 --object-record-bytes 100 -o "$TMP/m2.png" --stats "$TMP/m2.json"
sim_ok mem-entry "$img1" --size 8x8 --list-entry-bytes 2 -o "$TMP/m3.png" --stats "$TMP/m3.json"
sim_ok mem-both "$img1" --size 8x8 --list-entry-bytes 2 --cell-header-bytes 0 -o "$TMP/m4.png" --stats "$TMP/m4.json"
w0=$(json "$TMP/m0.json" .memory.whole_scene_bytes) w1=$(json "$TMP/m1.json" .memory.whole_scene_bytes)
w2=$(json "$TMP/m2.json" .memory.whole_scene_bytes) w3=$(json "$TMP/m3.json" .memory.whole_scene_bytes)
w4=$(json "$TMP/m4.json" .memory.whole_scene_bytes)
check "a 0-byte cell header saves 4 x 13824 bytes ($w0 - $w1)" [ $((w0 - w1)) -eq $((4 * 13824)) ]
check "100-byte records add 80 bytes to each of 369 spheres ($w2 - $w0)" [ $((w2 - w0)) -eq $((369 * 80)) ]
check "2-byte entries save 2 bytes an entry ($w0 - $w3)" [ $((w0 - w3)) -gt 0 -a $(((w0 - w3) % 2)) -eq 0 ]
check "the savings add up ($w4)" [ "$w4" -eq $((w0 - (w0 - w1) - (w0 - w3))) ]
check "the image does not depend on the accounting" cmp -s "$TMP/m0.png" "$TMP/m4.png"
scene=$img1 size=(--size 8x8)
bad_option --cell-header-bytes "negative header" --cell-header-bytes -1
bad_option --list-entry-bytes "zero-byte entry" --list-entry-bytes 0
bad_option --object-record-bytes "huge record" --object-record-bytes 5000

# 4. The paper's machine files load, and name their timing file beside themselves: the same
#    machine from any working folder.
for m in "$SRC"/machines/*.toml; do
    [ -e "$m" ] || { fail "no machine files in $SRC/machines"; break; }
    name=$(basename "$m" .toml)
    (cd "$TMP" && "$sim" --dump-config --config "$m" >"$TMP/$name.dump" 2>"$TMP/$name.err")
    check "$name loads from another folder ($(head -c 200 "$TMP/$name.err"))" [ $? -eq 0 ]
    check "$name: its timing file is found beside it" \
        grep -qx "timing=\"$SRC/machines/timing/fitted.timing\"" "$TMP/$name.dump"
done
mkdir -p "$TMP/m/timing"
printf 'bus_cycle 3\n' >"$TMP/m/timing/slow.timing"
printf 'ips="2"\ncluster="2"\ntiming="timing/slow.timing"\n' >"$TMP/m/slow.toml"
sim_ok relative-timing "$img1" --size 8x8 --config "$TMP/m/slow.toml" -o "$TMP/rel.png" --stats "$TMP/rel.json"
check "a relative timing path is read beside the machine file" [ "$(json "$TMP/rel.json" .config.timing.bus_cycle)" = 3 ]
(cd "$TMP/m" && "$sim" --dump-config --config slow.toml --timing "$SRC/timing/literal.timing" >"$TMP/cl.dump")
check "--timing on the command line is taken as given" \
    grep -qx "timing=\"$SRC/timing/literal.timing\"" "$TMP/cl.dump"
sim_ok paper-16 "$img1" --size 16x16 --config "$SRC/machines/paper-16.toml" -o "$TMP/p16.png" --stats "$TMP/p16.json"
"${run_limited[@]}" "$render" "$img1" --size 16x16 -q -o "$TMP/p16-ref.png"
check "paper-16.toml renders the reference image" cmp -s "$TMP/p16.png" "$TMP/p16-ref.png"

# 5. Round one's reading stays selectable by name: its machine files run its profile, interleave
#    and tie rule on its scenes, and equal the same run spelt out as options.
for m in "$SRC"/machines/round-one/*.toml; do
    [ -e "$m" ] || { fail "no machine files in $SRC/machines/round-one"; break; }
    name=round-one-$(basename "$m" .toml)
    (cd "$TMP" && "$sim" --dump-config --config "$m" >"$TMP/$name.dump" 2>"$TMP/$name.err")
    check "$name loads ($(head -c 200 "$TMP/$name.err"))" [ $? -eq 0 ]
    check "$name: profile round-one" grep -qx 'timing-profile="round-one"' "$TMP/$name.dump"
    check "$name: block-cyclic:3" grep -qx 'map="block-cyclic:3"' "$TMP/$name.dump"
    check "$name: ties plus" grep -qx 'route-ties="plus"' "$TMP/$name.dump"
done
old1=$SRC/scenes/paper-image1-planar-z.nff
sim_ok round-one "$old1" --size 16x16 --config "$SRC/machines/round-one/paper-16.toml" -o "$TMP/r1.png" --stats "$TMP/r1.json"
sim_ok round-one-spelt "$old1" --size 16x16 --ips 4x2x2 --map block-cyclic:3 --route-ties plus \
    --timing-profile round-one -o "$TMP/r1s.png" --stats "$TMP/r1s.json"
check "round one's machine file = its options spelt out" \
    [ "$(json "$TMP/r1.json" .sim_time_s)" = "$(json "$TMP/r1s.json" .sim_time_s)" ]
check "round one's machine file differs from the fitted one" \
    [ "$(json "$TMP/r1.json" .sim_time_s)" != "$(json "$TMP/p16.json" .sim_time_s 2>/dev/null)" ]
"${run_limited[@]}" "$render" "$old1" --size 16x16 -q -o "$TMP/r1-ref.png"
check "round one's machine renders the reference image" cmp -s "$TMP/r1.png" "$TMP/r1-ref.png"

finish
