#!/usr/bin/env bash
# The buffer study in quick mode (32x32, capacities 1, 4 and unbounded): experiments/buffers/study.sh
# runs every point through GNU parallel and writes runs.tsv, the plot and the Markdown page; every
# class-scheme run finishes with the renderer's image, no buffer exceeds its capacity, and the
# scheme's unbounded times equal one class's.
source "$(dirname "$0")/common.bash" "$@"
for tool in parallel gnuplot jq; do
    command -v $tool >/dev/null || { fail "$tool not installed"; finish; exit 1; }
done
bash "$SRC/experiments/buffers/study.sh" --quick --results "$TMP/res" --build "$BUILD" -j 2 2>"$TMP/err"
check "study exits 0 ($(tail -n 1 "$TMP/err"))" test $? -eq 0
runs=$TMP/res/runs.tsv
check "48 runs listed" test "$(tail -n +2 "$runs" | wc -l)" -eq 48
check "every class-scheme run ok with the reference image" test -z "$(awk -F'\t' \
    'NR > 1 && $4 == "classes" && ($6 != "ok" || $7 != 1 || $16 != "true")' "$runs")"
check "unbounded: the scheme's time equals one class's" test -z "$(awk -F'\t' \
    'NR > 1 && $5 == 0 { t[$1 FS $2 FS $4] = $8 } END { for (k in t) { split(k, a, FS);
      if (a[3] == "classes" && t[k] != t[a[1] FS a[2] FS "none"]) print k } }' "$runs")"
check "page says every run finished" grep -q "renderer's image and conserved packets: yes" "$TMP/res/buffers.md"
check "page says no buffer over capacity" grep -q "than its capacity: yes" "$TMP/res/buffers.md"
check "plot written" test -s "$TMP/res/buffers/time-vs-capacity.png"
finish
