#!/usr/bin/env bash
# grid_vs_bruteforce.sh - the grid gives the same image as testing every object, and renders
# are deterministic, for every scene in SOURCE_DIR/scenes.
#
# For each scene: render with --brute-force and with --cells 1, 7, 24 and 64; every grid PNG
# must equal the brute-force PNG byte for byte (cmp). Scenes with more than 400 objects are
# skipped for this (a brute-force render would take too long) with a note, except the
# paper's two images, which always run, at 48x48. Then every scene (all of them) is
# rendered twice at default settings and the two PNGs must be byte-identical.
# paper-image1 and paper-image2 must exist.
#
# Usage (CTest runs it so): bash tests/cli/grid_vs_bruteforce.sh BUILD_DIR SOURCE_DIR
# $TORUSRT_SCENE_DIR, when set, replaces SOURCE_DIR/scenes.
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-render
max_objects=400
time_limit 300

# Objects in an NFF file, roughly: one per s, p or c, n - 2 per `pp n` (comments dropped).
# NFF is a token stream, so tokens are counted, not lines.
count_objects() {
    sed 's/#.*//' "$1" | tr -s ' \t\r' '\n\n\n' | awk '
        want_pp { n = $0 + 0; count += (n > 2 ? n - 2 : 0); want_pp = 0; next }
        $0 == "s" || $0 == "p" || $0 == "c" { count++ }
        $0 == "pp" { want_pp = 1 }
        END { print count + 0 }'
}

# render_to NAME OUT ARGS...: renders $scene, reporting a failure (with stderr) if it does not work.
render_to() { render_ok "$1" "$scene" "${@:2}"; }

shopt -s nullglob
scenes=("$SCENE_DIR"/*.nff)
for required in paper-image1 paper-image2; do
    if [ ! -f "$SCENE_DIR/$required.nff" ]; then
        fail "$required: scene file missing: $SCENE_DIR/$required.nff"
    fi
done
if [ ${#scenes[@]} -eq 0 ]; then
    fail "grid_vs_bruteforce: no .nff files in $SCENE_DIR"
    finish
    exit 1
fi

for scene in "${scenes[@]}"; do
    name=$(basename "$scene" .nff)
    objects=$(count_objects "$scene")
    size=()
    case $name in
    paper-image1 | paper-image2) size=(--size 48x48) ;;
    *)
        if [ "$objects" -gt "$max_objects" ]; then
            echo "note: $name: $objects objects (> $max_objects), brute-force comparison skipped"
            size=(skip)
        fi
        ;;
    esac
    if [ "${size[0]:-}" != skip ]; then
        bf="$TMP/$name.bf.png"
        if render_to "$name" "$bf" --brute-force "${size[@]}"; then
            for cells in 1 7 24 64; do
                out="$TMP/$name.cells$cells.png"
                render_to "$name" "$out" --cells "$cells" "${size[@]}" || continue
                if cmp -s "$bf" "$out"; then
                    pass
                else
                    fail "$name: --cells $cells differs from --brute-force ($(cmp -l "$bf" "$out" 2>/dev/null | wc -l) bytes of the PNG differ)"
                fi
            done
        fi
    fi
    # Determinism at default settings.
    a="$TMP/$name.a.png"
    b="$TMP/$name.b.png"
    if render_to "$name" "$a" && render_to "$name" "$b"; then
        if cmp -s "$a" "$b"; then
            pass
        else
            fail "$name: two renders at default settings differ"
        fi
    fi
    rm -f "$TMP/$name".*.png
done

finish
