#!/usr/bin/env bash
# The README's what-if table and the summary agree: every row whose command runs torusrt-sim is
# run (at a smaller image, in a scratch folder), and each word its "look at" column quotes
# (`image time`, `busy per IP`, ...; file names and options to add aside) is found in that run's summary. A word
# the summary does not print fails the test naming the row.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
readme=$SRC/README.md
mkdir -p "$TMP/run/build"
ln -s "$SRC/scenes" "$TMP/run/scenes"
ln -s "$BUILD/torusrt-sim" "$TMP/run/build/torusrt-sim"
# The table's rows, "command<TAB>look at": the first `...` of the command cell, the look-at cell.
python3 - "$readme" >"$TMP/rows" <<'PY'
import re, sys
rows, on = [], False
for line in open(sys.argv[1]):
    if line.startswith("| question | command | look at |"):
        on = True
        continue
    if on and not line.startswith("|"):
        break
    if on and not line.startswith("| ---"):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        command = re.findall(r"`([^`]*)`", cells[1])
        if command:
            print(command[0] + "\t" + cells[2])
PY
check "the README has a what-if table of 10 rows or more ($(wc -l <"$TMP/rows"))" test "$(wc -l <"$TMP/rows")" -ge 10
sim_rows=0
while IFS=$'\t' read -r command look; do
    case $command in '$sim '*|'build/torusrt-sim '*) ;; *) continue ;; esac
    sim_rows=$((sim_rows + 1))
    # $sim as the README defines it, at 32x32 for speed; every output in the scratch folder.
    command=${command//'$sim'/build/torusrt-sim scenes/paper-image1.nff --size 72x72}
    command=${command//--size 72x72/--size 32x32}
    command=${command//--size 64x64/--size 32x32}
    (cd "$TMP/run" && eval "$command") >"$TMP/summary" 2>"$TMP/stderr" </dev/null
    rc=$?
    check "row '$command' runs (exit $rc: $(head -c 300 "$TMP/stderr"))" test $rc -eq 0
    while IFS= read -r word; do
        case $word in *.png|*.csv|*.json|*.vcd|*.gtkw|--*) continue ;; esac  # an output file or an option to add
        check "row '$command': the summary prints '$word'" grep -qF -- "$word" "$TMP/summary"
    done < <(grep -o '`[^`]*`' <<<"$look" | tr -d '`')
done <"$TMP/rows"
check "rows with a torusrt-sim command: $sim_rows" test "$sim_rows" -ge 8
finish
