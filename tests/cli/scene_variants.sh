#!/usr/bin/env bash
# torusrt-genscenes --variant: the paper images' scene-work variants (docs/fidelity-protocol.md).
# - the default values write the objects, view and lights of paper-image1-planar-z and
#   paper-image2-floor (round one's images) exactly;
# - scale multiplies every radius of image 1 and keeps every centre; radius moves image 2's two
#   big spheres to x = -+(r + 0.3), y = r + 0.5 and keeps the 121 small ones;
# - lights=1 and 3 write that many lights, with the same total intensity per channel;
# - a larger margin widens the view angle, a smaller one narrows it;
# - a variant renders, and the model on 2x2x2 gives the renderer's image;
# - bad settings (out of range, not the project's number syntax, a key twice, an empty item) and
#   bad NAMEs exit 2 naming the fault, and write no file;
# - a link in the temporary's place is removed, not written through; an output link is followed;
# - --help and --list to a full device exit 1.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-genscenes torusrt-render torusrt-sim
gen="$BUILD/torusrt-genscenes"
out="$TMP/v"
mkdir -p "$out"
# body FILE: the scene without its comment lines.
body() { grep -v '^#' "$1"; }
# field FILE PREFIX: the lines starting with PREFIX.
field() { grep "^$2" "$1"; }

"$gen" --variant paper-image1 layout=planar-z,scale=1,lights=2,margin=1.03 "$out" d1 >/dev/null
check "image 1 defaults: paper-image1-planar-z's body" cmp -s <(body "$out/d1.nff") <(body "$SRC/scenes/paper-image1-planar-z.nff")
"$gen" --variant paper-image2 plane=floor,radius=2,lights=2,margin=1.02 "$out" d2 >/dev/null
check "image 2 defaults: paper-image2-floor's body" cmp -s <(body "$out/d2.nff") <(body "$SRC/scenes/paper-image2-floor.nff")
"$gen" --variant paper-image1 layout=cube "$out" cube >/dev/null
check "layout=cube: paper-image1-cube's body" cmp -s <(body "$out/cube.nff") <(body "$SRC/scenes/paper-image1-cube.nff")

"$gen" --variant paper-image1 scale=0.8 "$out" s08 >/dev/null
check "scale=0.8: 369 spheres" test "$(field "$out/s08.nff" 's ' | wc -l)" = 369
check "scale=0.8: the same centres" cmp -s <(field "$out/s08.nff" 's ' | cut -d' ' -f1-4) \
    <(field "$SRC/scenes/paper-image1-planar-z.nff" 's ' | cut -d' ' -f1-4)
check "scale=0.8: every radius x 0.8" test "$(paste -d' ' <(field "$out/s08.nff" 's ' | cut -d' ' -f5) \
    <(field "$SRC/scenes/paper-image1-planar-z.nff" 's ' | cut -d' ' -f5) |
    awk '{ d = $1 - 0.8 * $2; if (d < 0) d = -d; if (d > 1e-9) bad++ } END { print bad + 0 }')" = 0

"$gen" --variant paper-image2 radius=2.5 "$out" r25 >/dev/null
check "radius=2.5: the glass sphere at (-2.8, 3, -2)" grep -qx 's -2.8 3 -2 2.5' "$out/r25.nff"
check "radius=2.5: the mirror sphere at (2.8, 3, -2)" grep -qx 's 2.8 3 -2 2.5' "$out/r25.nff"
check "radius=2.5: the 121 small spheres kept" cmp -s <(field "$out/r25.nff" 's ' | tail -n 121) \
    <(field "$SRC/scenes/paper-image2-floor.nff" 's ' | tail -n 121)

# sum_lights FILE: the lights' intensities added per channel.
sum_lights() { field "$1" 'l ' | awk '{ r += $5; g += $6; b += $7 } END { printf "%.6f %.6f %.6f\n", r, g, b }'; }
for image in 1 2; do
    for n in 1 3; do
        "$gen" --variant "paper-image$image" "lights=$n" "$out" "l$image$n" >/dev/null
        check "image $image lights=$n: $n light lines" test "$(field "$out/l$image$n.nff" 'l ' | wc -l)" = "$n"
        check "image $image lights=$n: the same total intensity" test \
            "$(sum_lights "$out/l$image$n.nff")" = "$(sum_lights "$SRC/scenes/paper-image$image.nff")"
    done
done

angle() { field "$1" 'angle ' | cut -d' ' -f2; }
"$gen" --variant paper-image1 margin=1.25 "$out" wide >/dev/null
"$gen" --variant paper-image1 margin=0.8 "$out" tight >/dev/null
base=$(angle "$SRC/scenes/paper-image1-planar-z.nff")
check "margin=1.25 widens the view" awk -v a="$(angle "$out/wide.nff")" -v b="$base" 'BEGIN { exit !(a > b) }'
check "margin=0.8 narrows the view" awk -v a="$(angle "$out/tight.nff")" -v b="$base" 'BEGIN { exit !(a < b) }'

"$gen" --variant paper-image1 layout=tree,scale=1.25,lights=3,margin=0.8 "$out" mix >/dev/null
if "$BUILD/torusrt-render" "$out/mix.nff" --size 24x24 -q -o "$TMP/mix-ref.png" &&
    "$BUILD/torusrt-sim" "$out/mix.nff" --size 24x24 --ips 2x2x2 --t1 1 -q -o "$TMP/mix-sim.png"; then
    check "a variant renders; the model's image is the renderer's" cmp -s "$TMP/mix-ref.png" "$TMP/mix-sim.png"
else
    fail "a variant did not render or simulate"
fi

# bad VARIANT SETTINGS WORD: exit 2, WORD in the message, no file.
bad() {
    rm -f "$out/bad.nff"
    "$gen" --variant "$1" "$2" "$out" bad >/dev/null 2>"$TMP/bad.err"
    local rc=$?
    check "$1 $2: exit 2 (got $rc)" test "$rc" = 2
    check "$1 $2: names $3 ($(head -c 160 "$TMP/bad.err"))" grep -q -- "$3" "$TMP/bad.err"
    check "$1 $2: no file" test ! -e "$out/bad.nff"
}
bad paper-image1 scale=0 scale
bad paper-image1 scale=.8 scale
bad paper-image1 scale=0.8x scale
bad paper-image1 lights=4 lights
bad paper-image1 lights=1.5 lights
bad paper-image1 lights=1.0 "whole number"
bad paper-image1 layout=wall layout
bad paper-image1 radius=2 "layout, scale"
bad paper-image2 scale=2 "plane, radius"
bad paper-image2 plane=cube plane
bad paper-image2 margin=nan margin
bad paper-image3 lights=1 paper-image3
bad paper-image1 lights "KEY=VALUE"
bad paper-image1 lights=03 lights
bad paper-image1 scale=010 "leading zero (decimal only"
bad paper-image1 scale=0x1 "hexadecimal is not accepted"
bad paper-image1 scale=+1 "is not a number"
bad paper-image1 scale=inf "is not a number"
bad paper-image1 scale=1e-400 "too close to 0"
bad paper-image1 lights=2e0 "whole number"
bad paper-image1 scale=1,scale=2 "given twice"
bad paper-image1 scale=1, "empty"
bad paper-image1 "" "empty"

# The one strict syntax takes an exponent: scale=1e0 is scale 1.
"$gen" --variant paper-image1 scale=1e0 "$out" e0 >/dev/null
"$gen" --variant paper-image1 scale=1 "$out" e1 >/dev/null
check "scale=1e0 is scale=1 (the same scene but for its name)" cmp -s <(sed 1d "$out/e0.nff") <(sed 1d "$out/e1.nff")
# --list and --help take nothing after them (an option given twice is refused).
"$gen" --list --list >/dev/null 2>"$TMP/list.err"
rc=$?
check "--list --list: exit 2 (got $rc)" test "$rc" = 2
check "--list --list: says why ($(head -c 120 "$TMP/list.err"))" grep -q "takes nothing after it" "$TMP/list.err"

# NAME: a file name, not a path, an option or a hidden file; nothing written.
for name in "" "a/b" $'ev2\nl 0 0 0\n#' "-x" ".hidden"; do
    rm -rf "$out/n" && mkdir "$out/n"
    "$gen" --variant paper-image1 scale=1 "$out/n" "$name" >/dev/null 2>"$TMP/name.err"
    rc=$?
    check "NAME '$name': exit 2 (got $rc)" test "$rc" = 2
    check "NAME '$name': names NAME" grep -q "NAME" "$TMP/name.err"
    check "NAME '$name': nothing written" test -z "$(ls -A "$out/n")"
done
# A scene named twice in the plain form: refused before anything is written (it would be written
# twice and counted as two scenes).
rm -rf "$out/n" && mkdir "$out/n"
"$gen" "$out/n" paper-image1 paper-image2 paper-image1 >/dev/null 2>"$TMP/twice.err"
rc=$?
check "a scene named twice: exit 2 (got $rc)" test "$rc" = 2
check "a scene named twice: says so" grep -q "scene 'paper-image1' named twice" "$TMP/twice.err"
check "a scene named twice: nothing written" test -z "$(ls -A "$out/n")"
# A control byte in NAME is shown escaped: the message stays one line.
"$gen" --variant paper-image1 scale=1 "$out/n" $'ev2\nl' >/dev/null 2>"$TMP/name.err"
check "NAME with a newline: shown as \\x0a" grep -qF "'ev2\x0al'" "$TMP/name.err"
check "NAME with a newline: a one-line message" test "$(wc -l <"$TMP/name.err")" = 1

# The temporary is a new .NAME.nff.XXXXXX: a file or link of the user's named NAME.nff.tmp is
# neither removed nor written through, and no temporary is left; an output that is a link is
# followed: its target is written and the link stays.
mkdir -p "$TMP/links/gx"
cp "$SRC/scenes/paper-image1-planar-z.nff" "$TMP/links/keep.nff"
cp "$SRC/scenes/paper-image1-planar-z.nff" "$TMP/links/target.nff"
ln -s ../keep.nff "$TMP/links/gx/paper-image2-floor.nff.tmp"
"$gen" "$TMP/links/gx" paper-image2-floor >/dev/null 2>&1
check "a link in the temporary's place: the file it names is untouched" \
    cmp -s "$TMP/links/keep.nff" "$SRC/scenes/paper-image1-planar-z.nff"
check "a link in the temporary's place: the scene written" cmp -s "$TMP/links/gx/paper-image2-floor.nff" \
    "$SRC/scenes/paper-image2-floor.nff"
check "a link named NAME.nff.tmp stays" test -L "$TMP/links/gx/paper-image2-floor.nff.tmp"
echo precious >"$TMP/links/gx/v1.nff.tmp"
(umask 022 && "$gen" --variant paper-image1 scale=1 "$TMP/links/gx" v1 >/dev/null 2>&1)
check "a file named NAME.nff.tmp is kept as it was" test "$(cat "$TMP/links/gx/v1.nff.tmp")" = precious
check "the variant written beside it" test -s "$TMP/links/gx/v1.nff"
check "the scene's mode is the umask's (0644), not mkstemp's" test "$(stat -c %a "$TMP/links/gx/v1.nff")" = 644
check "no temporary left" test -z "$(find "$TMP/links/gx" -name '.*')"
ln -s ../target.nff "$TMP/links/gx/v.nff"
"$gen" --variant paper-image1 scale=0.8 "$TMP/links/gx" v >/dev/null 2>&1
check "an output link stays a link" test -L "$TMP/links/gx/v.nff"
check "an output link: its target holds the variant" cmp -s <(body "$TMP/links/target.nff") <(body "$out/s08.nff")

# Standard output that cannot take the help or the list: exit 1, said.
if [ -w /dev/full ]; then
    "$gen" --help >/dev/full 2>"$TMP/full.err"
    check "--help > /dev/full: exit 1" test $? = 1
    "$gen" --list >/dev/full 2>>"$TMP/full.err"
    check "--list > /dev/full: exit 1" test $? = 1
    check "/dev/full: the message says standard output" grep -q "standard output" "$TMP/full.err"
fi
finish
