#!/usr/bin/env bash
# machine_tables.sh - machine files grouped in tables ([network], [timing], [cluster], [mapping]),
# read with toml++: a grouped file, a flat one and the two mixed make the same machine as the
# command line; a key in another table than its own, a table that is none of these, a key given
# twice (flat and in its table), hex, underscores, inf, nan and signs in numbers, arrays, inline
# tables, dates, bytes that are not UTF-8 and TOML syntax errors exit 2 naming the file, the line
# and the column, and print no dump.
#
# Usage (CTest runs it so): bash tests/hostile/machine_tables.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
time_limit 30
sim="$BUILD/torusrt-sim"

# The dump is grouped: four tables in order, each key in its table, and it reads back to itself.
"$sim" --dump-config --ips 2x2 --cluster 2 --map block > "$TMP/d.toml" 2> "$TMP/err"
check "--dump-config exits 0 ($(head -1 "$TMP/err"))" [ $? = 0 ]
check "the dump's tables in order ($(grep '^\[' "$TMP/d.toml" | tr '\n' ' '))" \
    [ "$(grep '^\[' "$TMP/d.toml" | tr '\n' ' ')" = "[network] [timing] [cluster] [mapping] " ]
table_of() { awk -v k="$1" '/^\[/ { t = $0 } index($0, k "=") == 1 { print t }' "$TMP/d.toml"; }
for kt in ips:network queue:network link-us:timing quantum:timing cluster:cluster dispatch:cluster \
    map:mapping replicate:mapping; do
    check "${kt%%:*} in [${kt#*:}] ($(table_of "${kt%%:*}"))" [ "$(table_of "${kt%%:*}")" = "[${kt#*:}]" ]
done
"$sim" --dump-config --config "$TMP/d.toml" > "$TMP/d2.toml" 2> "$TMP/err"
check "a dump of the dump is the same file ($(head -1 "$TMP/err"))" cmp -s "$TMP/d.toml" "$TMP/d2.toml"

# A hand-written grouped file, a flat one and a mixed one are the machine of the command line.
"$sim" --dump-config --ips 2x2 --queue 8 --style lt --quantum 500us --cluster 4 --data shared \
    --map block-cyclic:3 > "$TMP/want.toml"
printf '# grouped\n[network]\nips = "2x2"\nqueue = 8\n\n[timing]\nstyle = "lt"\nquantum = "500us"\n[cluster]\ncluster = 4\ndata = '"'shared'"'\n[mapping]\nmap = "block-cyclic:3"\n' > "$TMP/grouped.toml"
printf 'ips="2x2"\nqueue="8"\nstyle="lt"\nquantum="500us"\ncluster="4"\ndata="shared"\nmap="block-cyclic:3"\n' > "$TMP/flat.toml"
printf 'ips="2x2"\nstyle="lt"\n[network]\nqueue=8\n[timing]\nquantum="500us"\n[cluster]\ncluster=4\ndata="shared"\n[mapping]\nmap="block-cyclic:3"\n' > "$TMP/mixed.toml"
for form in grouped flat mixed; do
    "$sim" --dump-config --config "$TMP/$form.toml" > "$TMP/$form.dump" 2> "$TMP/err"
    check "the $form file reads ($(head -1 "$TMP/err"))" [ $? = 0 ]
    check "the $form file is the command line's machine ($(diff "$TMP/want.toml" "$TMP/$form.dump" | head -3 | tr '\n' ' '))" \
        cmp -s "$TMP/want.toml" "$TMP/$form.dump"
done
# The example of docs/cli.md#machine-files reads.
awk '/^    # m.toml - four nodes/ { on = 1 } on && /^[^ ]/ { exit } on { sub(/^    /, ""); print }' \
    "$SRC/docs/cli.md" > "$TMP/doc.toml"
check "docs/cli.md's example found ($(grep -c . "$TMP/doc.toml") lines)" grep -q '^\[mapping\]' "$TMP/doc.toml"
"$sim" --dump-config --config "$TMP/doc.toml" > "$TMP/doc.dump" 2> "$TMP/err"
check "docs/cli.md's example reads ($(head -1 "$TMP/err"))" grep -qx 'data="shared"' "$TMP/doc.dump"
# Dotted keys are the same table.
printf 'network.ips = "2x2"\n' > "$TMP/dotted.toml"
"$sim" --dump-config --config "$TMP/dotted.toml" > "$TMP/dotted.dump" 2> "$TMP/err"
check "network.ips reads ($(head -1 "$TMP/err"))" grep -qx 'ips="2x2x1"' "$TMP/dotted.dump"

# bad_file EXPECTED CONTENT: exit 2, stderr holds "bad.toml:LINE:COLUMN: ..." (EXPECTED, a
# grep pattern), nothing on stdout.
bad_file() {
    printf '%b' "$2" > "$TMP/bad.toml"
    "$sim" --dump-config --config "$TMP/bad.toml" > "$TMP/out" 2> "$TMP/err"
    local rc=$?
    check "'$2' exits 2 (got $rc)" [ $rc = 2 ]
    check "'$2': message 'bad.toml:$1' ($(head -1 "$TMP/err"))" grep -q -- "bad.toml:$1" "$TMP/err"
    check "'$2': no dump" [ ! -s "$TMP/out" ]
}
# Tables.
bad_file "2:1: ips: a key of \[network\], not of \[timing\]" '[timing]\nips="2"\n'
bad_file "3:1: quantum: a key of \[timing\], not of \[network\]" 'style="lt"\n[network]\nquantum="1ms"\n'
bad_file "1:2: \[netwrk\]: not a table of a machine file .*did you mean \[network\]" '[netwrk]\nips="2"\n'
bad_file "1:10: \[network.x\]: a machine file's tables hold no tables" '[network.x]\nips="2"\n'
bad_file "1:3: \[\[network\]\]: an array of tables" '[[network]]\nips="2"\n'
bad_file "1:1: network: an inline table" 'network = { ips = "2" }\n'
bad_file "2:1: ips: an inline table" '[network]\nips = { x = "2" }\n'
bad_file "2:1: frobnicate: not a machine option" '[network]\nfrobnicate="2"\n'
# Twice: flat and in its table (toml++ itself refuses twice in one table).
bad_file "3:1: ips: given twice (also at 1:5)" 'ips="2"\n[network]\nips="3"\n'
bad_file "3:1: .*cannot redefine existing table" '[network]\nips="2"\n[network]\nips="3"\n'
# Numbers go through the option's parser, as on the command line.
bad_file "2:7: --queue '0x10': decimal only" '[network]\nqueue=0x10\n'
bad_file "2:7: --queue '1_000': expected a whole decimal number" '[network]\nqueue=1_000\n'
bad_file "2:7: --queue '+5': expected a whole decimal number" '[network]\nqueue=+5\n'
bad_file "2:7: --queue '-1': expected a whole decimal number" '[network]\nqueue=-1\n'
bad_file "2:11: --replicate 'inf': expected a decimal number" '[mapping]\nreplicate=inf\n'
bad_file "2:11: --replicate 'nan': expected a decimal number" '[mapping]\nreplicate=nan\n'
bad_file "2:19: --link-bytes-per-us '0x1p3': decimal only" '[timing]\nlink-bytes-per-us="0x1p3"\n'
bad_file "2:10: .*leading zeroes are prohibited" '[network]\nqueue=010\n'
bad_file "1:1: quantum = \"0.5\": a time in a machine file needs its unit" 'quantum=0.5\n'
# Arrays, dates, booleans for a choice, bytes that are not UTF-8, TOML syntax.
bad_file "2:1: ips: an array" '[network]\nips=["2", "2"]\n'
bad_file "2:1: quantum: a date or time" '[timing]\nquantum=1979-05-27\n'
bad_file "1:9: --style 'true'" 'style = true\n'
bad_file "1:8: .*invalid utf-8" 'timing="\xff.timing"\n'
bad_file "2:6: .*expected digit" '[network]\nips=2x2\n'
bad_file "3:4: .*expected '='" '[network]\nips="2"\nmap\n'
# A value that comes from the file names it at the value's line and column.
bad_file "3:7: --ips 'zz'" '# comment\n[network]\nips = "zz"\n'

# Numbers that are decimal read as on the command line.
printf '[network]\nqueue = 16\n[mapping]\nreplicate = 0.25\nmap = "cost"\n' > "$TMP/num.toml"
"$sim" --dump-config --config "$TMP/num.toml" > "$TMP/num.dump" 2> "$TMP/err"
check "decimal numbers read ($(head -1 "$TMP/err"))" grep -qx 'queue="16"' "$TMP/num.dump"
check "a decimal real reads" grep -qx 'replicate="0.25"' "$TMP/num.dump"
finish
