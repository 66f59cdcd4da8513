#!/usr/bin/env bash
# stiff_scenes.sh - the stiff scenes of docs/design.md section 9 through torusrt-render.
#
# Every stiff scene (written by scenes/gen_scenes.c) must exist, render with exit 0 to a PNG
# of the scene's resolution, and conserve packets (--stats: created == consumed). Then:
#   scale-pow2-tiny and scale-pow2-huge give PNGs byte-identical to scale-1;
#   scale-tiny, scale-huge and tiny-sphere render at scale-1's / tiny-sphere-alone's size
#     (their pixel tolerance, <= 2 levels on 99.5 % of pixels and never > 64, is checked in
#     memory by kernel_tests RenderStiffScale.DecimalScalesAreClose and
#     RenderStiffTiny.TinySphereBesideAHugeOneMatchesItAlone: a PNG is compressed, so
#     counting differing file bytes says nothing about pixels);
#   facing-mirrors: --max-depth 8 is the default, and the depth-8 rays change the image;
#   empty: every primary ray misses the space and nothing is shaded;
#   eye-inside: every primary ray starts inside the space;
#   one-pixel: a 1x1 PNG of a hit.
# A missing scene file is a failure naming it.
#
# Usage (CTest runs it so): bash tests/cli/stiff_scenes.sh BUILD_DIR SOURCE_DIR
# $TORUSRT_SCENE_DIR, when set, replaces SOURCE_DIR/scenes.
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-render
have_jq=1
if ! command -v jq >/dev/null 2>&1; then
    have_jq=0
    echo "note: jq not found: the --stats checks are skipped"
fi
time_limit 300

scenes=(scale-1 scale-tiny scale-huge scale-pow2-tiny scale-pow2-huge tiny-sphere tiny-sphere-alone
    facing-mirrors light-inside tir grazing axis-rays grid-corners eye-inside empty one-cell
    one-big-sphere cones-and-patches one-pixel)

# png_size FILE: "WIDTH HEIGHT" from the IHDR chunk.
png_size() {
    od -An -tu1 -j16 -N8 "$1" | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4, $5 * 16777216 + $6 * 65536 + $7 * 256 + $8 }'
}
# scene_resolution FILE: "WIDTH HEIGHT" from the view's `resolution` (token stream).
scene_resolution() {
    sed 's/#.*//' "$1" | tr -s ' \t\r' '\n\n\n' | awk 'take == 2 { w = $0; take = 1; next } take == 1 { print w + 0, $0 + 0; exit } $0 == "resolution" { take = 2 }'
}
# render_scene NAME OUT.png [ARGS...]: renders with --stats OUT.json; fails loudly if it cannot.
render_scene() { render_ok "$1" "$SCENE_DIR/$1.nff" "$2" --stats "${2%.png}.json" "${@:3}"; }

declare -A ok
for name in "${scenes[@]}"; do
    file="$SCENE_DIR/$name.nff"
    if [ ! -f "$file" ]; then
        fail "$name: scene file missing: $file"
        continue
    fi
    png="$TMP/$name.png"
    render_scene "$name" "$png" || continue
    ok[$name]=1
    pass
    want=$(scene_resolution "$file")
    got=$(png_size "$png")
    check "$name: PNG is $got, the scene asks for $want" [ "$got" = "$want" ]
    if [ "$have_jq" -eq 1 ]; then
        stats="$TMP/$name.json"
        check "$name: ray packets created != consumed" \
            [ "$(json "$stats" .packets.created.ray)" = "$(json "$stats" .packets.consumed.ray)" ]
        check "$name: shadow packets created != consumed" \
            [ "$(json "$stats" .packets.created.shadow)" = "$(json "$stats" .packets.consumed.shadow)" ]
    fi
done

# Power-of-two scales: exact products, so the same image byte for byte.
for name in scale-pow2-tiny scale-pow2-huge; do
    if [ -n "${ok[scale-1]:-}" ] && [ -n "${ok[$name]:-}" ]; then
        check "$name: PNG differs from scale-1's" cmp -s "$TMP/scale-1.png" "$TMP/$name.png"
    fi
done
# Decimal scales and the tiny sphere: same size here; pixels are compared in kernel_tests.
for pair in scale-tiny:scale-1 scale-huge:scale-1 tiny-sphere:tiny-sphere-alone; do
    a=${pair%%:*}
    b=${pair#*:}
    if [ -n "${ok[$a]:-}" ] && [ -n "${ok[$b]:-}" ]; then
        check "$a: PNG size differs from $b's" [ "$(png_size "$TMP/$a.png")" = "$(png_size "$TMP/$b.png")" ]
    fi
done

# Facing mirrors: the depth limit.
if [ -n "${ok[facing-mirrors]:-}" ]; then
    d8="$TMP/fm8.png"
    d7="$TMP/fm7.png"
    if render_scene facing-mirrors "$d8" --max-depth 8 && render_scene facing-mirrors "$d7" --max-depth 7; then
        check "facing-mirrors: --max-depth 8 differs from the default" cmp -s "$TMP/facing-mirrors.png" "$d8"
        check "facing-mirrors: depth-8 rays change nothing (--max-depth 7 gives the same image)" \
            bash -c "! cmp -s '$d7' '$d8'"
        if [ "$have_jq" -eq 1 ]; then
            r8=$(json "${d8%.png}.json" .packets.created.ray)
            r7=$(json "${d7%.png}.json" .packets.created.ray)
            check "facing-mirrors: no more ray packets at --max-depth 8 ($r8) than at 7 ($r7)" [ "$r8" -gt "$r7" ]
        fi
    fi
fi

if [ "$have_jq" -eq 1 ]; then
    if [ -n "${ok[empty]:-}" ]; then
        j="$TMP/empty.json"
        pixels=$(($(json "$j" .width) * $(json "$j" .height)))
        check "empty: primary rays missing the space != pixels" [ "$(json "$j" .packets.primary_missed)" = "$pixels" ]
        check "empty: something was shaded" [ "$(json "$j" .ops.shadings)" = 0 ]
    fi
    if [ -n "${ok[eye-inside]:-}" ]; then
        check "eye-inside: a primary ray missed the space although the eye is inside it" \
            [ "$(json "$TMP/eye-inside.json" .packets.primary_missed)" = 0 ]
    fi
    if [ -n "${ok[one-pixel]:-}" ]; then
        check "one-pixel: the single ray shaded nothing" [ "$(json "$TMP/one-pixel.json" .ops.shadings)" -ge 1 ]
    fi
fi
if [ -n "${ok[one-pixel]:-}" ]; then
    check "one-pixel: PNG is not 1x1" [ "$(png_size "$TMP/one-pixel.png")" = "1 1" ]
fi

finish
