#!/usr/bin/env bash
# docs/cli.md's generated option tables are those torusrt-sim writes from its option tables
# (--option-tables), so a default, range, unit, key or JSON key changed in the table and not in
# the docs fails here; and the machine file's table of keys lists every key --dump-config writes.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
check "docs/cli.md's generated tables agree with torusrt-sim --option-tables" \
    python3 "$SRC/scripts/write_option_docs.py" "$BUILD" --check
"$BUILD/torusrt-sim" --dump-config | sed -n 's/^\([a-z-]*\)=.*/\1/p' | sort > "$TMP/dumped.txt"
"$BUILD/torusrt-sim" --option-tables | sed -n '/BEGIN generated: machine file tables/,/END generated/p' |
    grep -o '`[a-z-]*`' | tr -d '`' | sort > "$TMP/documented.txt"
check "the generated table has a key" test -s "$TMP/documented.txt"
check "the table of keys is --dump-config's keys (with map-file)" \
    diff <(sort -u "$TMP/dumped.txt" <(echo map-file)) "$TMP/documented.txt"
finish
