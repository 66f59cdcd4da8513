#!/usr/bin/env bash
# run_point.sh - run one point of the sweep, idempotently.
#
#   experiments/run_point.sh OUT.json [--t1-from T1.json] -- TORUSRT-SIM SCENE ARGS...
#
# Runs the given torusrt-sim command with -q -o OUT.png --stats OUT.json (and --t1 taken from the
# sim_time_s of T1.json; with --stats-interval and no --stats-series, also --stats-series
# OUT.series.csv), writing the files under temporary names in the same folder and renaming them
# into place only when the run succeeded and the JSON parses: a point is done exactly when
# OUT.json exists. If OUT.json already exists the point is skipped. On failure the simulator's
# messages are kept in OUT.log and the exit status is non-zero. A name that is a link is
# followed to its file (the link kept); a folder, a FIFO or a device as OUT.json, OUT.png,
# OUT.log or OUT.series.csv, or any of them naming a file of the command (the scene, a --timing
# file, a file a --config machine file names), is refused (exit 2) before the command runs, and
# so is a command that gives -o or --stats itself or whose output option (--vcd, --stats-series,
# ...) names one of these files, or that gives --help, --version or --dump-config (-h, -oFILE
# and --stats=FILE are seen too). T1.json must be a regular file of at most 64 MiB: a FIFO, a
# device or a folder is refused (exit 2, naming --t1-from) before it is read; its sim_time_s
# must be a number above 0 (else exit 3, as when it has none), and the command may not give --t1 too
# (exit 2). An empty OUT.json or no command after -- is a usage error (exit 2). Standard output
# or error redirected to a file the command line names (`2>> SCENE`) is refused (exit 2) before
# anything is written. A stopping signal (INT, TERM, HUP, QUIT, USR1, USR2, ALRM) sent to this
# script alone stops the command too (TERM), leaves no temporary and ends with `run_point: stopped
# by SIGNAME` and 128 + the signal's number.
set -uo pipefail
usage="usage: run_point.sh OUT.json [--t1-from T1.json] -- COMMAND..."
# Standard output or error redirected into a file of the command line (the scene, a --config) or
# into one of the point's own files (OUT.json, OUT.log, OUT.png, OUT.series.csv, which the run writes):
# refused (exit 2) before any message could be appended to it.
if [ -f /dev/stdout ] || [ -f /dev/stderr ]; then
    own=()
    [ -z "${1:-}" ] || { stem=${1%.json}; own=("$1" "$stem.log" "$stem.png" "$stem.series.csv"); }
    python3 "$(dirname "${BASH_SOURCE[0]}")/output_files.py" --check-streams run_point --own "${own[@]}" -- "$@" || exit 2
fi
[ $# -ge 1 ] && [ -n "$1" ] || { echo "run_point: $usage (OUT.json: not an empty value)" >&2; exit 2; }
out=$1
shift
t1args=()
t1_max_bytes=$((64 << 20))  # a point's JSON is a few MiB at most; jq holds it whole
if [ "${1:-}" = --t1-from ]; then
    t1json=${2:-}
    shift 2 || { echo "run_point: --t1-from needs a file" >&2; exit 2; }
    # A FIFO may never open and a device never end: only a regular file is read.
    if [ -e "$t1json" ] && [ ! -f "$t1json" ]; then
        echo "run_point: --t1-from '$t1json': not a regular file (a folder, a FIFO or a device)" >&2
        exit 2
    fi
    if [ -f "$t1json" ] && [ "$(stat -L -c %s -- "$t1json")" -gt "$t1_max_bytes" ]; then
        echo "run_point: --t1-from '$t1json': larger than 64 MiB, not a point's JSON" >&2
        exit 2
    fi
    # A positive number only: a string ("0.5ms") would reach torusrt-sim as --t1 0.5ms, and 0 (or
    # 1e-400, which jq reads as 0) as a --t1 every run refuses.
    if ! t1=$(jq -er '.sim_time_s | numbers | select(. > 0)' "$t1json" 2>/dev/null); then
        echo "run_point: $out: no T(1) in $t1json (no sim_time_s number above 0 in it; run the phase-1 points first)" >&2
        exit 3
    fi
    t1args=(--t1 "$t1")
fi
[ "${1:-}" = -- ] || { echo "run_point: expected -- before the command" >&2; exit 2; }
shift
[ $# -ge 1 ] && [ -n "$1" ] || { echo "run_point: no command after -- ($usage)" >&2; exit 2; }
if [ ${#t1args[@]} -gt 0 ]; then
    for word in "$@"; do
        case $word in
            --t1 | --t1=*) echo "run_point: --t1 in the command and --t1-from: give T(1) once" >&2; exit 2 ;;
        esac
    done
fi
dir=$(dirname "$out")
base=$(basename "$out" .json)
mkdir -p "$dir"
# The files the point writes, each a link followed to the file it names (the link is kept); a
# folder, a FIFO or a device is refused (experiments/output_files.py's rules).
json=$(realpath -m -- "$out") png=$(realpath -m -- "$dir/$base.png") log=$(realpath -m -- "$dir/$base.log")
series=$(realpath -m -- "$dir/$base.series.csv")
for f in "$json" "$png" "$log" "$series"; do
    if [ -e "$f" ] && [ ! -f "$f" ]; then
        echo "run_point: $f: not a regular file (a folder, a FIFO or a device)" >&2
        exit 2
    fi
done
# None of them may be a file the command reads (a word naming a file, or FILE of --option=FILE,
# and the files a --config machine file names): the point would write over its own input.
if ! python3 "$(dirname "${BASH_SOURCE[0]}")/output_files.py" --check-outputs "$json" "$png" "$log" "$series" -- "$@"; then
    exit 2
fi
if [ -s "$json" ] && jq -e '.sim_time_s' "$json" >/dev/null 2>&1; then
    echo "skip $out (done)"
    exit 0
fi
tag=.$base.tmp.$(hostname -s 2>/dev/null || echo host).$$
tmpjson=$(dirname "$json")/$tag.json tmppng=$(dirname "$png")/$tag.png tmplog=$(dirname "$log")/$tag.log
tmpseries=$(dirname "$series")/$tag.series.csv
# A series named from --stats would be named from the temporary: it gets its own name.
seriesargs=()
for word in "$@"; do
    case $word in --stats-series | --stats-series=*) seriesargs=(); break ;; esac
    case $word in --stats-interval | --stats-interval=*) seriesargs=(--stats-series "$tmpseries") ;; esac
done
trap 'rm -f "$tmpjson" "$tmppng" "$tmplog" "$tmplog.full" "$tmpseries"' EXIT
# The command runs as in_child's child (experiments/stop_signals.sh), so that a stopping signal
# sent to this script alone (INT, TERM, HUP, QUIT, USR1, USR2, ALRM) reaches it: the script stops
# it (TERM: a background command ignores INT), waits for it, says so and leaves no temporary (the
# EXIT trap), ending with 128 + the signal's number.
STOP_PROGRAM=run_point STOP_NOTE=""
# shellcheck source=experiments/stop_signals.sh
source "$(dirname "${BASH_SOURCE[0]}")/stop_signals.sh"
# into_log COMMAND...: COMMAND in place of the background shell, its messages into the log (the
# script's own message on a signal still goes to its standard error).
into_log() { exec "$@" >"$tmplog" 2>&1; }
rc=0
in_child into_log "$@" "${t1args[@]}" -q -o "$tmppng" --stats "$tmpjson" "${seriesargs[@]}" || rc=$?
if [ $rc -eq 0 ] && ! jq -e '.sim_time_s' "$tmpjson" >/dev/null 2>&1; then
    echo "torusrt-sim exited 0 but wrote no valid statistics" >>"$tmplog"
    rc=4
fi
if [ $rc -ne 0 ]; then
    { echo "# $(date -u +%FT%TZ) on $(hostname): exit $rc"; printf '%q ' "$@" "${t1args[@]}"; echo; cat "$tmplog"; } >"$tmplog.full"
    mv -f "$tmplog.full" "$log"
    echo "run_point: $out failed (exit $rc):" >&2
    sed 's/^/  /' "$tmplog" | tail -n 20 >&2
    exit $rc
fi
rm -f "$log"
mv -f "$tmppng" "$png"
[ ${#seriesargs[@]} -eq 0 ] || mv -f "$tmpseries" "$series"
mv -f "$tmpjson" "$json"
