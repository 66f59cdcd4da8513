#!/usr/bin/env bash
# Every machine option's default as docs/cli.md's table documents it is the value a run without
# the option uses: a run given the documented default reports the JSON `config` of a run given
# no machine option (the written-back options and every key of the block, the timing table's
# included).
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
sim=$BUILD/torusrt-sim
scene=$SRC/scenes/paper-image1.nff
run=(--size 8x8 --t1 1 -q)

# The rows of the generated machine options table that have a default: "--option default".
sed -n '/BEGIN generated: machine options/,/END generated: machine options/p' "$SRC/docs/cli.md" |
    awk -F ' [|] ' '$1 ~ /^[|] `--/ && $3 != "" { gsub(/`/, "", $1); gsub(/`/, "", $3); sub(/^[|] /, "", $1); print $1, $3 }' \
        >"$TMP/defaults.txt"
count=$(grep -c . "$TMP/defaults.txt")
check "docs/cli.md documents defaults of the machine options (found $count)" [ "$count" -ge 20 ]

"$sim" "$scene" "${run[@]}" -o "$TMP/none.png" --stats "$TMP/none.json" 2>"$TMP/err" ||
    fail "the run without machine options: $(head -c 200 "$TMP/err")"
jq -S .config "$TMP/none.json" >"$TMP/none.config"
check "the run without machine options reports a config" grep -q '"options"' "$TMP/none.config"

k=0
while read -r option default; do
    k=$((k + 1))
    if ! "$sim" "$scene" "${run[@]}" "$option" "$default" -o "$TMP/$k.png" --stats "$TMP/$k.json" 2>"$TMP/err"; then
        fail "$option $default: the run failed: $(head -c 200 "$TMP/err")"
        continue
    fi
    jq -S .config "$TMP/$k.json" >"$TMP/$k.config"
    check "$option: the documented default '$default' is the run's default ($(diff "$TMP/none.config" "$TMP/$k.config" | head -c 300))" \
        cmp -s "$TMP/none.config" "$TMP/$k.config"
done <"$TMP/defaults.txt"
finish
