#!/usr/bin/env bash
# The fidelity study end to end in its smoke mode (experiments/fidelity/study.sh --smoke): every
# stage runs on shrunk lists and sizes, and the page, the scenes and the machine files are
# written under the results folder only, never into the source tree's scenes/, machines/ or docs/.
# Checks: the page's first lines are the three counts; it has every stage's table, the fitted
# residuals, the roles, E_t1 and E_busy side by side and the dropped readings named; the machine
# files are cyclic with route-ties split and load in torusrt-sim; the fitted scene renders the
# reference image under them.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render torusrt-genscenes
command -v parallel >/dev/null || { fail "GNU parallel not installed"; finish; exit 1; }
study=$SRC/experiments/fidelity/study.sh
# The source tree's outputs, to see that the smoke mode leaves them alone.
tree_sum() { cat "$SRC"/scenes/paper-image[12].nff "$SRC"/machines/*.toml "$SRC"/machines/timing/* \
    "$SRC"/docs/fidelity.md 2>/dev/null | cksum; }
before=$(tree_sum)
bash "$study" --smoke --build "$BUILD" --results "$TMP/r" -j 2 >"$TMP/out" 2>&1
check "exit 0 ($(tail -n 3 "$TMP/out" | tr '\n' ' '))" test $? -eq 0
check "the source tree's scenes, machines and page untouched" test "$(tree_sum)" = "$before"
page=$TMP/r/out/docs/fidelity.md
check "the page is written" test -s "$page"
# The three counts first: the first lines under the page's '## Findings'.
counts=$(sed -n '/^## Findings$/,$p' "$page" | grep -m 3 '^- ')
check "first: claims holding" grep -qE '^- \*\*Claims holding: [0-9]+ of 17\.\*\*' <(sed -n 1p <<<"$counts")
check "second: fit targets holding" grep -qE '^- \*\*Fit targets holding: [0-9]+ of 8\*\*' <(sed -n 2p <<<"$counts")
check "third: validation claims holding" grep -qE '^- \*\*Validation claims holding: [0-9]+ of 9\*\*' <(sed -n 3p <<<"$counts")
check "the findings open the page" test "$(sed -n 3p "$page")" = "## Findings"
check "the opening every study page has (tests/reports/test_study_pages.py)" python3 -c "
import sys; sys.path.insert(0, sys.argv[1]); import test_study_pages as t
sys.exit(1 if t.opening_problems(open(sys.argv[2]).read()) else 0)" "$SRC/tests/reports" "$page"
for h in "### Stage 1: scenes and work" "### Stage 2: the bus (F3)" "### Stage 3: the 1024 times (F2)" \
    "### Stage 4: memory accounting (F4)" "## The fitted reading and its residuals" \
    "## Efficiency: E_t1 (primary) and E_busy side by side" "## Robustness: each claim"; do
    check "the page has '$h'" grep -qF "$h" "$page"
done
check "the validation's cluster points are means of two runs" \
    grep -qE '^\| image1-shared-m4 \| [0-9.]+ \| [0-9.]+ \| [0-9.]+ \| 2 \|$' "$page"
check "every claim's role" test "$(grep -cE '^\| [0-9]+ \| .* \| (fit target|validation)' "$page")" -ge 17
check "the dropped readings named" grep -qE '^\*\*Dropped readings\*\* \([0-9]+,.*ties-plus' "$page"
check "stage 2's table lists both bus pairs" test "$(grep -cE '^\| (0\.5 \| 0\.5|2 \| 1) \|' "$page")" -ge 2
for m in paper-16 paper-1024-replicated paper-1024-shared paper-192-replicated paper-192-shared; do
    f=$TMP/r/out/machines/$m.toml
    check "$m: cyclic, route-ties split" grep -qx 'route-ties="split"' "$f"
    check "$m: map cyclic" grep -qx 'map="cyclic"' "$f"
    "$BUILD/torusrt-sim" --dump-config --config "$f" >/dev/null 2>"$TMP/$m.err"
    check "$m loads ($(head -c 200 "$TMP/$m.err"))" test $? -eq 0
done
check "fitted.timing names the cell-step cost" grep -qE '^cell_step_packet [0-9]+$' "$TMP/r/out/machines/timing/fitted.timing"
for i in 1 2; do
    s=$TMP/r/out/scenes/paper-image$i.nff
    "$BUILD/torusrt-render" "$s" --size 16x16 -q -o "$TMP/ref$i.png" &&
        "$BUILD/torusrt-sim" "$s" --size 16x16 --config "$TMP/r/out/machines/paper-16.toml" -q -o "$TMP/sim$i.png"
    check "image $i: the fitted machine gives the reference image" cmp -s "$TMP/ref$i.png" "$TMP/sim$i.png"
done
finish
