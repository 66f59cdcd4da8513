#!/usr/bin/env bash
# machine_compare.sh - `experiments/report machine --compare` holds a report's machine against a
# machine file as torusrt-sim reads it: `ips="2"` is the report's 2x1x1, a default written out or
# left out is no difference, a real difference is named (exit 1); without a torusrt-sim in the
# default build folder the keys are compared as written, with a note; a --build given without
# one is refused (exit 2). File names holding a
# newline or an escape are shown escaped, each message on one line.
#
# Usage (CTest runs it so): bash tests/hostile/machine_compare.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim
command -v python3 >/dev/null || { echo "$TEST_NAME: python3 is not installed; skipped"; exit 77; }
time_limit 60
scene=$(source_scene paper-image1) || exit 1
export TORUSRT_BUILD=$BUILD  # the torusrt-sim that reads the --compare file
report=(python3 "$SRC/experiments/report" machine)
cd "$TMP" || exit 1
"${run_limited[@]}" "$BUILD/torusrt-sim" "$scene" -q --size 8x8 --t1 1 --ips 2 -o r.png --stats r.json </dev/null
check "the report's run: exit $?" [ -s r.json ]

# compares NAME STATUS PATTERN FILE [ARGS...]: report machine r.json --compare FILE exits STATUS,
# its stdout and stderr (in NAME.out) match PATTERN (grep -E).
compares() {
    local name=$1 status=$2 pattern=$3 file=$4
    shift 4
    "${run_limited[@]}" "${report[@]}" r.json --compare "$file" "$@" >"$name.out" 2>&1 </dev/null
    local rc=$?
    check "$name: exit $rc, expected $status: $(head -c 300 "$name.out")" [ "$rc" -eq "$status" ]
    check "$name: $pattern ($(head -c 300 "$name.out"))" grep -qE -e "$pattern" "$name.out"
}
printf 'ips="2x1x1"\n' >full.toml
compares "ips 2x1x1, the rest left out" 0 "r.json and full.toml: the same [0-9]+ keys" full.toml
printf 'ips="2"\n' >short.toml
compares "ips 2 for 2x1x1" 0 "the same [0-9]+ keys" short.toml
printf 'ips="2"\nmap="cyclic"\ncells="24"\nroute-ties="split"\n' >defaults.toml
compares "defaults written out" 0 "the same [0-9]+ keys" defaults.toml
printf 'ips="4"\ncells="24x24x12"\n' >other.toml
compares "another machine" 1 "^machine: ips: report '2x1x1', file '4x1x1'$" other.toml
check "another machine: cells named" grep -qxF "machine: cells: report '24x24x24', file '24x24x12'" "another machine.out"
check "another machine: two keys differ" grep -qE "other.toml: 2 keys differ$" "another machine.out"
printf 'ips="0"\n' >bad.toml
compares "a machine torusrt-sim refuses" 1 "^experiments/report: --compare 'bad.toml': torusrt-sim does not read it: .*--ips" bad.toml
# The default build folder ($TORUSRT_BUILD) without torusrt-sim: the keys as written, with a note;
# a --build given that holds none is a command-line error.
TORUSRT_BUILD=$TMP/none compares "no torusrt-sim" 1 \
    "^machine: no torusrt-sim in $TMP/none \(--build\): keys compared as written" short.toml
compares "a --build without torusrt-sim" 2 "^experiments/report: --build '$TMP/none': no torusrt-sim in it" \
    short.toml --build "$TMP/none"

# Names with a newline or an escape: escaped, every message one line.
cp short.toml $'new\nline.toml'
compares "a newline in the file's name" 0 '^machine: r.json and new\\x0aline.toml: the same' $'new\nline.toml'
check "a newline in the file's name: one line" [ "$(wc -l <"a newline in the file's name.out")" -eq 1 ]
"${run_limited[@]}" "${report[@]}" $'no\e[31msuch\n.json' >missing.out 2>&1 </dev/null
check "a missing report with an escape and a newline: exit $?" [ $? -eq 1 ]
check "a missing report: named escaped ($(head -c 200 missing.out))" grep -qF "'no\\x1b[31msuch\\x0a.json'" missing.out
check "a missing report: one line" [ "$(wc -l <missing.out)" -eq 1 ]
check "a missing report: no raw escape" bash -c "! grep -q $'\e' missing.out"

finish
