#!/usr/bin/env bash
# README.md is at most 250 lines and every relative link in README.md and docs/*.md resolves, to a
# file and to a heading of it; a broken link and an over-long README are caught (on copies).
source "$(dirname "$0")/common.bash" "$@"
checker="$SRC/scripts/check_doc_links.py"
out=$(python3 "$checker" "$SRC" 2>&1)
check "the documentation's links resolve and README.md is short: $out" test -z "$out"
mkdir -p "$TMP/tree/docs"
printf '# A\n\nSee [b](docs/b.md#part-two) and [c](docs/c.md).\n' > "$TMP/tree/README.md"
printf '# B\n\n## Part one\n\n`[not a link](nowhere.md)`\n' > "$TMP/tree/docs/b.md"
out=$(python3 "$checker" "$TMP/tree")
check "a missing heading is named" grep -q 'README.md:3: docs/b.md#part-two: no heading #part-two' <<< "$out"
check "a missing file is named" grep -q 'README.md:3: docs/c.md: no such file' <<< "$out"
check "a link in a code span is not a link" test "$(grep -c nowhere <<< "$out")" -eq 0
python3 "$checker" "$TMP/tree" > /dev/null
check "broken links fail the check" test $? -eq 1
printf '# B\n\n## Part two\n' > "$TMP/tree/docs/b.md"
printf '# C\n' > "$TMP/tree/docs/c.md"
check "the repaired tree passes" python3 "$checker" "$TMP/tree"
out=$(python3 "$checker" --max-readme-lines 2 "$TMP/tree")
check "a README over the limit is named" grep -q 'README.md: 3 lines, more than 2' <<< "$out"
finish
