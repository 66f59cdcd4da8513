#!/usr/bin/env bash
# run_point.sh - run one point of the sweep, idempotently.
#
#   experiments/run_point.sh OUT.json [--t1-from T1.json] -- TORUSRT-SIM SCENE ARGS...
#
# Runs the given torusrt-sim command with -q -o OUT.png --stats OUT.json (and --t1 taken from the
# sim_time_s of T1.json), writing both files under temporary names in the same folder and
# renaming them into place only when the run succeeded and the JSON parses: a point is done
# exactly when OUT.json exists. If OUT.json already exists the point is skipped. On failure the
# simulator's messages are kept in OUT.log and the exit status is non-zero.
set -uo pipefail
out=${1:?usage: run_point.sh OUT.json [--t1-from T1.json] -- COMMAND...}
shift
t1args=()
if [ "${1:-}" = --t1-from ]; then
    t1json=$2
    shift 2
    if ! t1=$(jq -er '.sim_time_s' "$t1json" 2>/dev/null); then
        echo "run_point: $out: no T(1) in $t1json (run the phase-1 points first)" >&2
        exit 3
    fi
    t1args=(--t1 "$t1")
fi
[ "${1:-}" = -- ] || { echo "run_point: expected -- before the command" >&2; exit 2; }
shift
if [ -s "$out" ] && jq -e '.sim_time_s' "$out" >/dev/null 2>&1; then
    echo "skip $out (done)"
    exit 0
fi
dir=$(dirname "$out")
base=$(basename "$out" .json)
mkdir -p "$dir"
tag=.$base.tmp.$(hostname -s 2>/dev/null || echo host).$$
tmpjson=$dir/$tag.json tmppng=$dir/$tag.png tmplog=$dir/$tag.log
trap 'rm -f "$tmpjson" "$tmppng" "$tmplog"' EXIT
"$@" "${t1args[@]}" -q -o "$tmppng" --stats "$tmpjson" >"$tmplog" 2>&1
rc=$?
if [ $rc -eq 0 ] && ! jq -e '.sim_time_s' "$tmpjson" >/dev/null 2>&1; then
    echo "torusrt-sim exited 0 but wrote no valid statistics" >>"$tmplog"
    rc=4
fi
if [ $rc -ne 0 ]; then
    { echo "# $(date -u +%FT%TZ) on $(hostname): exit $rc"; printf '%q ' "$@" "${t1args[@]}"; echo; cat "$tmplog"; } >"$dir/$base.log"
    echo "run_point: $out failed (exit $rc):" >&2
    sed 's/^/  /' "$tmplog" | tail -n 20 >&2
    exit $rc
fi
rm -f "$dir/$base.log"
mv -f "$tmppng" "$dir/$base.png"
mv -f "$tmpjson" "$out"
