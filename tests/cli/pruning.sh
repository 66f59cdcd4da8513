#!/usr/bin/env bash
# pruning.sh - shade-tree pruning (--max-depth, --min-weight) with torusrt-render and torusrt-sim:
# the default settings give the reference image byte for byte (explicit defaults too, and
# torusrt-sim on a torus); the PSNR against the default-settings image never falls as max-depth
# goes 0..8 or as min-weight goes 1/8..1/512, and the largest pixel difference never grows;
# torusrt-sim's image equals the renderer's at every setting. Also runs the pruning study script
# (experiments/error_vs_runtime/pruning.sh) on a small case and checks its CSV.
# Usage: bash pruning.sh BUILD_DIR SOURCE_DIR
source "$(dirname "$0")/common.bash" "$@"

CMP=$(TORUSRT_BUILD="$BUILD" bash -c 'source "$1/experiments/error_vs_runtime/common.sh"; png_compare_tool' _ "$SRC") ||
  { fail "no png_compare tool"; finish; exit 1; }

# psnr_ge A B: A >= B where either may be "inf".
psnr_ge() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "inf") exit 0; if (b == "inf") exit 1; exit !(a + 0 >= b + 0) }'; }

# png_compare itself: identical images are "inf 0 0 N".
"$BUILD/torusrt-render" "$SRC/scenes/paper-image2.nff" -o "$TMP/c.png" -q --size 16x12 || fail "render 16x12"
check "png_compare: an image against itself" test "$("$CMP" "$TMP/c.png" "$TMP/c.png")" = "inf 0 0 192"
"$BUILD/torusrt-render" "$SRC/scenes/paper-image2.nff" -o "$TMP/c0.png" -q --size 16x12 --max-depth 0 || fail "render 16x12 depth 0"
check "png_compare: a different image has a finite PSNR" \
  awk -v l="$("$CMP" "$TMP/c.png" "$TMP/c0.png")" 'BEGIN { split(l, f, " "); exit !(f[1] != "inf" && f[2] > 0 && f[4] == 192) }'
check "png_compare: a size mismatch is an error" bash -c '! "$1" "$2" "$3" 2>/dev/null' _ "$CMP" "$TMP/c.png" "$TMP/c.png.missing"

for c in "paper-image2 48x48 4x2x2" "facing-mirrors 40x40 2x2x2" "tir 40x40 4x2x1"; do
  read -r scene size ips <<<"$c"
  f="$SRC/scenes/$scene.nff"
  [ -f "$f" ] || { fail "missing scene $f"; continue; }
  "$BUILD/torusrt-render" "$f" -o "$TMP/ref.png" -q --size "$size" || { fail "$scene: reference render"; continue; }
  "$BUILD/torusrt-render" "$f" -o "$TMP/ref2.png" -q --size "$size" --max-depth 8 --min-weight 1/512 ||
    fail "$scene: render with explicit defaults"
  check "$scene: explicit defaults (max-depth 8, min-weight 1/512) give the reference" cmp -s "$TMP/ref.png" "$TMP/ref2.png"
  "$BUILD/torusrt-sim" "$f" -o "$TMP/simref.png" -q --size "$size" --ips "$ips" --t1 1 || fail "$scene: sim defaults"
  check "$scene: torusrt-sim $ips at the defaults equals the reference byte for byte" cmp -s "$TMP/ref.png" "$TMP/simref.png"

  prev_r="" prev_s="" prev_max="" psnrs=""
  for d in 0 1 2 3 4 5 6 7 8; do
    "$BUILD/torusrt-render" "$f" -o "$TMP/r$d.png" -q --size "$size" --max-depth "$d" || { fail "$scene: render depth $d"; continue; }
    "$BUILD/torusrt-sim" "$f" -o "$TMP/s$d.png" -q --size "$size" --ips "$ips" --max-depth "$d" --t1 1 ||
      { fail "$scene: sim depth $d"; continue; }
    read -r pr maxr _ _ < <("$CMP" "$TMP/ref.png" "$TMP/r$d.png")
    read -r ps _ _ _ < <("$CMP" "$TMP/ref.png" "$TMP/s$d.png")
    psnrs+=" $pr"
    check "$scene: sim image equals render image at max-depth $d" cmp -s "$TMP/r$d.png" "$TMP/s$d.png"
    if [ -n "$prev_r" ]; then
      check "$scene: render PSNR $pr dB at max-depth $d >= $prev_r dB at $((d - 1))" psnr_ge "$pr" "$prev_r"
      check "$scene: sim PSNR $ps dB at max-depth $d >= $prev_s dB at $((d - 1))" psnr_ge "$ps" "$prev_s"
      check "$scene: max abs diff $maxr at max-depth $d <= $prev_max at $((d - 1))" test "$maxr" -le "$prev_max"
    fi
    prev_r=$pr prev_s=$ps prev_max=$maxr
  done
  check "$scene: PSNR at max-depth 8 is inf (the reference)" test "$prev_r" = inf
  read -r first _ <<<"$psnrs"
  check "$scene: pruning changes the image at max-depth 0 (PSNR by depth:$psnrs)" test "$first" != inf

  prev=""
  for w in 1/8 1/32 1/128 1/512; do
    "$BUILD/torusrt-render" "$f" -o "$TMP/w.png" -q --size "$size" --min-weight "$w" || { fail "$scene: render min-weight $w"; continue; }
    read -r p _ _ _ < <("$CMP" "$TMP/ref.png" "$TMP/w.png")
    [ -n "$prev" ] && check "$scene: PSNR $p dB at min-weight $w >= $prev dB at the previous weight" psnr_ge "$p" "$prev"
    prev=$p
  done
  check "$scene: PSNR at min-weight 1/512 is inf" test "$prev" = inf
done

# The study script on a small case.
csv="$TMP/pruning.csv"
if bash "$SRC/experiments/error_vs_runtime/pruning.sh" --build "$BUILD" --out "$csv" --scenes paper-image2 --ips 4x2x2 \
     --size 32x32 --depths "0 4 8" --weights "1/512 1/8" --reps 1 2>"$TMP/pruning.log"; then
  check "study: 3 + 2 + 1 settings on 2 runners" test "$(($(wc -l < "$csv") - 1))" -eq 12
  check "study: every sim image equals the renderer's" test "$(awk -F, 'NR > 1 && $15 != "true"' "$csv" | wc -l)" -eq 0
  check "study: PSNR inf at the defaults" awk -F, '$2 == "max_depth" && $3 == 8 { n++; if ($11 != "inf") bad = 1 } END { exit !(n == 2 && !bad) }' "$csv"
  check "study: PSNR finite at max-depth 0" awk -F, '$2 == "max_depth" && $3 == 0 && $11 == "inf" { bad = 1 } END { exit bad }' "$csv"
else
  fail "study: pruning.sh failed: $(tail -n 3 "$TMP/pruning.log")"
fi
finish
