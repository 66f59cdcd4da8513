#!/usr/bin/env bash
# scenes_uptodate.sh - the checked-in scenes/*.nff are exactly what torusrt-genscenes writes.
#
# Usage: bash tests/cli/scenes_uptodate.sh BUILD_DIR SOURCE_DIR
# Runs BUILD_DIR/torusrt-genscenes into a temporary folder, compares every file byte for byte
# with SOURCE_DIR/scenes/NAME.nff (and NAME.motion; paper-image1 and paper-image2 as the --variant
# their notes name, when the fidelity study wrote them so), checks that the two sets of names (and --list) agree, that
# the paper's scenes hold 369 and 123 objects, and that the generator is deterministic.
# Prints "N passed, M failed"; exits 1 on any failure.
set -u
source "$(dirname "$0")/common.bash" "$@"
gen="$BUILD/torusrt-genscenes"
scenes="$SRC/scenes"

if [ ! -x "$gen" ]; then
    fail "$gen does not exist or is not executable"
    finish
    exit 1
fi

# 1. Generate everything.
mkdir -p "$TMP/a" "$TMP/b"
if "$gen" "$TMP/a" >"$TMP/log" 2>&1; then
    pass
else
    fail "torusrt-genscenes $TMP/a exited non-zero:"
    sed 's/^/    /' "$TMP/log"
    finish
    exit 1
fi

# variant_spec FILE: the KEY=VALUE,... of a scene torusrt-genscenes --variant wrote (its notes name
# every value), or nothing for a scene of the generator's list.
variant_spec() {
    sed -n '2,4p' "$1" | tr '\n' ' ' | sed -n \
        -e 's/^# A variant of the paper.s image 1 .*layout \([a-z-]*\),.*radius x \([0-9.e+-]*\) .*, \([0-9]*\) light(s).*margin \([0-9.e+-]*\)\. *$/layout=\1,scale=\2,lights=\3,margin=\4/p' \
        -e 's/^# A variant of the paper.s image 2 .*plane \([a-z]*\),.*of radius \([0-9.e+-]*\), \([0-9]*\) light(s).*margin \([0-9.e+-]*\)\. *$/plane=\1,radius=\2,lights=\3,margin=\4/p'
}
# The fitted paper images (experiments/fidelity/study.sh writes them with --variant): generated
# again from the values their notes give, into the folder compared below.
mkdir -p "$TMP/v"
for image in 1 2; do
    f=$scenes/paper-image$image.nff
    spec=$(variant_spec "$f" 2>/dev/null)
    [ -n "$spec" ] || continue
    "$gen" --variant "paper-image$image" "$spec" "$TMP/v" "paper-image$image" >/dev/null &&
        cp "$TMP/v/paper-image$image.nff" "$TMP/a/" || fail "paper-image$image.nff: --variant $spec failed"
done

# 2. Every generated file (scenes and motion files) is checked in, byte for byte (the paper
#    images as their variant, when they are one).
for f in "$TMP"/a/*.nff "$TMP"/a/*.motion; do
    [ -e "$f" ] || { fail "the generator wrote no .nff files"; break; }
    name=$(basename "$f")
    if [ ! -f "$scenes/$name" ]; then
        fail "$name is generated but scenes/$name is not checked in"
    elif cmp -s "$f" "$scenes/$name"; then
        pass
    else
        fail "scenes/$name differs from the generator's output" \
             "(regenerate: build/torusrt-genscenes scenes)"
        diff "$scenes/$name" "$f" | head -n 10 | sed 's/^/    /'
    fi
done

# 3. Every checked-in scene and motion file is generated.
for f in "$scenes"/*.nff "$scenes"/*.motion; do
    [ -e "$f" ] || continue
    name=$(basename "$f")
    if [ -f "$TMP/a/$name" ]; then
        pass
    else
        fail "scenes/$name is checked in but torusrt-genscenes does not write it"
    fi
done
# A motion file belongs to the scene of its name.
for f in "$scenes"/*.motion; do
    [ -e "$f" ] || continue
    [ -f "${f%.motion}.nff" ] && pass || fail "$(basename "$f") has no scene ${f%.motion}.nff"
done

# 4. --list names the same set.
if "$gen" --list >"$TMP/list" 2>&1; then
    listed=$(awk '{print $1 ".nff"}' "$TMP/list" | sort)
    written=$(cd "$TMP/a" && ls -1 -- *.nff | sort)
    if [ "$listed" = "$written" ]; then
        pass
    else
        fail "--list and the written files disagree"
        diff <(echo "$listed") <(echo "$written") | sed 's/^/    /'
    fi
else
    fail "torusrt-genscenes --list exited non-zero"
fi

# 5. The paper's object counts.
count_objects() { awk '$1 == "s" || $1 == "p" || $1 == "pp" || $1 == "c" {n++} END {print n + 0}' "$1"; }
f1="$scenes/paper-image1.nff"
if [ -f "$f1" ]; then
    spheres=$(grep -c '^s ' "$f1")
    objects=$(count_objects "$f1")
    if [ "$spheres" -eq 369 ] && [ "$objects" -eq 369 ]; then
        pass
    else
        fail "paper-image1.nff: $spheres 's ' lines and $objects objects, want 369 spheres only"
    fi
    if awk '$1 == "f" && ($6 != 0 || $8 != 0) {bad = 1} END {exit bad}' "$f1"; then
        pass
    else
        fail "paper-image1.nff has a material with Ks or T not 0 (must be diffuse only)"
    fi
else
    fail "scenes/paper-image1.nff is missing"
fi
f2="$scenes/paper-image2.nff"
if [ -f "$f2" ]; then
    objects=$(count_objects "$f2")
    if [ "$objects" -eq 123 ]; then
        pass
    else
        fail "paper-image2.nff has $objects objects, want 123 (2 large + 121 small spheres)"
    fi
else
    fail "scenes/paper-image2.nff is missing"
fi
for f in "$f1" "$f2"; do
    [ -f "$f" ] || continue
    if grep -q '^resolution 144 144$' "$f"; then
        pass
    else
        fail "$(basename "$f") is not 144 x 144"
    fi
done

# 6. Deterministic: a second run, and a run naming two scenes, write the same bytes;
#    no temporary files are left behind.
if "$gen" "$TMP/b" paper-image1-planar-z one-cell >/dev/null 2>&1 &&
    cmp -s "$TMP/a/paper-image1-planar-z.nff" "$TMP/b/paper-image1-planar-z.nff" &&
    cmp -s "$TMP/a/one-cell.nff" "$TMP/b/one-cell.nff" &&
    [ "$(ls -1 "$TMP/b" | wc -l)" -eq 2 ]; then
    pass
else
    fail "writing only paper-image1 and one-cell did not reproduce the same two files"
fi
if ls "$TMP"/a/*.tmp >/dev/null 2>&1; then
    fail "temporary .tmp files left behind"
else
    pass
fi

# 7. Errors: unknown name and unwritable folder exit non-zero and write nothing.
mkdir -p "$TMP/c"
if "$gen" "$TMP/c" no-such-scene >/dev/null 2>&1; then
    fail "an unknown scene name did not make torusrt-genscenes fail"
elif [ -n "$(ls -A "$TMP/c")" ]; then
    fail "an unknown scene name still wrote files"
else
    pass
fi
if "$gen" "$TMP/missing/folder" empty >/dev/null 2>&1; then
    fail "writing into a missing folder did not make torusrt-genscenes fail"
else
    pass
fi

finish
