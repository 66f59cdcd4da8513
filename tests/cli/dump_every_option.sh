#!/usr/bin/env bash
# dump_every_option.sh - the machine file --dump-config writes is complete: for every option of
# the machine's table (the help's machine group, which the table generates), a run given a
# non-default value of it and a run from the dump of the same options simulate the same image
# time and report the same JSON `config`; the dump holds the key in the table the report's
# config.option_tables names, and the dump without its tables (a flat file) reads back to the
# same dump. An option of the table without a sample value here fails the test, so a new
# machine option gets its check.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
sim="$BUILD/torusrt-sim"
scene=$(source_scene paper-image1) || exit 1
run=(--size 8x8 --t1 1 -q)

printf 'link 77\nhost_inject 3\n' >"$TMP/own.timing"
{ echo "torusrt-map 1 2 2 2 2"; for c in 0 1 2 3 4 5 6 7; do echo $(((c / 3) % 2)); done; } >"$TMP/own.map"

# Each machine option with the options that make a non-default value of it valid.
declare -A sample=(
    [--ips]="--ips 2x2"
    [--map]="--ips 4 --map block"
    [--topology]="--ips 4 --topology mesh"
    [--route-ties]="--ips 4x2 --route-ties split"
    [--cells]="--ips 2 --cells 6"
    [--preprocess-count]="--preprocess-count per-plane"
    [--queue]="--ips 2 --queue 4"
    [--flow]="--ips 2 --flow none"
    [--queue-order]="--ips 4 --queue-order rays-first"
    [--timing-profile]="--timing-profile literal"
    [--timing]="--timing $TMP/own.timing"
    [--timing-values]="--ips 2 --timing-values link=400,host_inject=9"
    [--link-us]="--ips 2 --link-us 500"
    [--packet-bytes]="--ips 2 --packet-bytes 56 --link-bytes-per-us 1"
    [--link-bytes-per-us]="--ips 2 --link-bytes-per-us 2"
    [--link-setup-us]="--ips 2 --link-setup-us 5"
    [--max-depth]="--max-depth 1"
    [--min-weight]="--min-weight 0.5"
    [--style]="--ips 2 --style lt --quantum 1ms"
    [--quantum]="--ips 2 --style lt --quantum 300us"
    [--cluster]="--cluster 2"
    [--data]="--cluster 2 --data shared"
    [--arbiter]="--cluster 4 --data shared --arbiter fixed-priority"
    [--dispatch]="--cluster 4 --dispatch shortest-queue"
    [--cell-header-bytes]="--cell-header-bytes 12"
    [--list-entry-bytes]="--list-entry-bytes 8"
    [--object-record-bytes]="--object-record-bytes 64"
    [--map-file]="--ips 2 --cells 2 --map-file $TMP/own.map"
    [--pilot-size]="--ips 4 --map cost --pilot-size 4x4"
    [--replicate]="--ips 4 --map scatter --replicate 0.5"
    [--replica-choice]="--ips 4 --map scatter --replicate 0.5 --replica-choice hash"
)

# The machine options, from the help's machine group, less the group's options that read and
# write machine files themselves.
"$sim" --help >"$TMP/help.txt" || fail "--help"
options=$(awk '/^Machine /{on=1; next} on && /^[A-Z]/{on=0} on' "$TMP/help.txt" |
    grep -oE '^ +--[a-z0-9-]+' | tr -d ' ' | grep -vxE -- '--(config|dump-config|with-timing)')
count=$(printf '%s\n' "$options" | grep -c .)
check "the help lists the machine options (found $count)" [ "$count" -ge 20 ]

k=0
for option in $options; do
    k=$((k + 1))
    if [ -z "${sample[$option]:-}" ]; then
        fail "$option: no sample value in $(basename "$0"): add one"
        continue
    fi
    read -r -a args <<<"${sample[$option]}"
    "$sim" "$scene" "${run[@]}" "${args[@]}" -o "$TMP/a$k.png" --stats "$TMP/a$k.json" 2>"$TMP/err" ||
        { fail "$option: the run with ${args[*]}: $(head -c 200 "$TMP/err")"; continue; }
    "$sim" --dump-config "${args[@]}" >"$TMP/d$k.toml" 2>"$TMP/err" ||
        { fail "$option: --dump-config: $(head -c 200 "$TMP/err")"; continue; }
    "$sim" "$scene" "${run[@]}" --config "$TMP/d$k.toml" -o "$TMP/b$k.png" --stats "$TMP/b$k.json" 2>"$TMP/err" ||
        { fail "$option: the run from the dump: $(head -c 200 "$TMP/err")"; continue; }
    a=$(json_get "$TMP/a$k.json" sim_time_s) b=$(json_get "$TMP/b$k.json" sim_time_s)
    check "$option: the run from the dump takes the same image time ($a, $b)" test -n "$a" -a "$a" = "$b"
    check "$option: the run from the dump reports the same config" \
        cmp -s <(jq -S .config "$TMP/a$k.json") <(jq -S .config "$TMP/b$k.json")
    check "$option: the dump holds its key" grep -q "^${option#--}=\"..*\"" "$TMP/d$k.toml"
    # The key in its table, the one the report names; the same file flat is the same machine.
    table=$(awk -v k="${option#--}=" '/^\[/ { t = $0 } index($0, k) == 1 { print t }' "$TMP/d$k.toml")
    want=$(jq -r --arg k "${option#--}" '.config.option_tables[$k]' "$TMP/a$k.json")
    check "$option: in the table the report names ($table, [$want])" test "$table" = "[$want]"
    grep -v -e '^\[' -e '^$' "$TMP/d$k.toml" >"$TMP/f$k.toml"
    "$sim" --dump-config --config "$TMP/f$k.toml" >"$TMP/f$k.dump" 2>"$TMP/err"
    check "$option: the dump without its tables (flat) is the same machine ($(head -c 200 "$TMP/err"))" \
        cmp -s "$TMP/d$k.toml" "$TMP/f$k.dump"
done
finish
