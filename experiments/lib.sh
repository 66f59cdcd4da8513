# shellcheck shell=bash
# shellcheck disable=SC2034  # the settings are used by the scripts that source this file
# lib.sh - shared settings for the reproduction scripts (sourced, not run).
# Sets EXP (this folder), REPO (the source tree), BUILD (the build folder) and SIM (torusrt-sim).
# The build folder comes from --build DIR (parsed by each script), else $TORUSRT_BUILD,
# else REPO/build.
EXP=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO=$(cd "$EXP/.." && pwd)
BUILD=${TORUSRT_BUILD:-$REPO/build}

die() { echo "$(basename "$0"): $*" >&2; exit 2; }

# The script's command line, for check_places (the scripts take their options off "$@").
SCRIPT_ARGS=("$@")

# write_file FILE [OPTION]: standard input into FILE under the output rules of the Python tools
# (output_files.py: through a temporary renamed into place, a link followed, a folder, FIFO or
# device refused naming OPTION, exit 2).
write_file() { python3 "$EXP/output_files.py" "$@"; }

# show_help END: the comment block at the top of the running script, from its second line to the
# line matching END, as --help prints it; exit 0, or 1 with "SCRIPT: standard output: cannot
# write: REASON" when standard output cannot take it (a full disk, a closed pipe).
show_help() {
    sed -n "2,/$1/p" "$0" | sed '$d; s/^# \{0,1\}//' | python3 "$EXP/output_files.py" --stdout "$(basename "$0")"
    exit $?
}

# make_folder OPTION DIR: DIR made (with its parents) for OPTION's results; a DIR that is a file,
# or a parent that is one, ends the command (exit 2) naming OPTION, before anything is written.
make_folder() {
    local err
    [ ! -e "$2" ] || [ -d "$2" ] || die "$1 '$2': is a file, not a folder"
    err=$(mkdir -p -- "$2" 2>&1) || die "$1 '$2': cannot make the folder: ${err##*: }"
}

# set_build DIR [EXE...]: make BUILD absolute and check the executables are there (torusrt-sim
# and each EXE), before any point runs: a folder without them would fail every point.
set_build() {
    local dir=$1 exe
    shift
    [ -n "$dir" ] || die "--build: an empty value (name the build folder)"
    [ -d "$dir" ] || die "build folder '$dir' does not exist (configure and build first, or pass --build / TORUSRT_BUILD)"
    BUILD=$(cd "$dir" && pwd)
    SIM=$BUILD/torusrt-sim
    for exe in torusrt-sim "$@"; do
        [ -x "$BUILD/$exe" ] || die "build folder '$dir' has no $exe (build it first, or pass --build / TORUSRT_BUILD)"
    done
    check_tmpdir
}

# file_kind PATH: what PATH that is not a regular file is, as the executables say it ("is a FIFO").
file_kind() {
    if [ -d "$1" ]; then echo "is a folder"
    elif [ -p "$1" ]; then echo "is a FIFO"
    elif [ -c "$1" ]; then echo "is a character device"
    elif [ -b "$1" ]; then echo "is a block device"
    elif [ -S "$1" ]; then echo "is a socket"
    else echo "is a special file"; fi
}

# check_tmpdir: a TMPDIR that is set must be a folder one can write into: GNU parallel and
# torusrt-sim (--vcd) make their temporaries there, and would fail every point without saying why.
check_tmpdir() {
    [ -z "${TMPDIR:-}" ] || { [ -d "$TMPDIR" ] && [ -w "$TMPDIR" ] && [ -x "$TMPDIR" ]; } ||
        die "TMPDIR '$TMPDIR': not a folder this user can write into (GNU parallel and torusrt-sim make their temporaries there; set it to one, or unset it)"
}

# need_value OPTION ARGS...: ends the command (exit 2) naming OPTION when ARGS (the words after
# it) are none or start with an empty word: an empty value is never taken as the default; or when
# OPTION was given before (given_once).
need_value() {
    [ $# -ge 2 ] || die "$1 needs a value"
    [ -n "$2" ] || die "$1: an empty value"
    given_once "$1"
}

# given_once OPTION: ends the command (exit 2) when OPTION (or OPTION=VALUE) came before on the
# command line, as the executables do: the last one does not silently win.
declare -A GIVEN_OPTIONS=()
given_once() {
    local name=${1%%=*}
    [ -z "${GIVEN_OPTIONS[$name]:-}" ] || die "$name: given 2 times; give it once"
    GIVEN_OPTIONS[$name]=1
}

# abspath PATH: absolute form of a path whose parent exists (the path itself need not).
abspath() { local d; d=$(cd "$(dirname "$1")" && pwd) || return 1; echo "$d/$(basename "$1")"; }

# The readings of the paper's unknowns a sweep runs under (docs/fidelity.md), each from the
# environment, the reading's (use_reading, below) when unset:
#   TORUSRT_SHAPE16        the arrangement of 16 nodes, flat and clustered
#   TORUSRT_LB_MAP         what the load-balancing ("cyclic") points run
#   TORUSRT_SCENE_IMAGE1/2 the scene files of image 1 and image 2
#   TORUSRT_POINT_ARGS     more torusrt-sim arguments for every point, split at spaces (after the
#                          reading's own)
#   TORUSRT_MAPS           the full mode's mappings (default "block cyclic bc2 bc3")
read -r -a POINT_ARGS <<<"${TORUSRT_POINT_ARGS:-}"
# The paper's 3D torus shapes for each IP count (16: the reading's arrangement, use_reading).
declare -A SHAPE=([1]=1x1x1 [2]=2x1x1 [4]=2x2x1 [8]=2x2x2 [16]=4x2x2 [32]=4x4x2 [64]=4x4x4
                  [128]=8x4x4 [256]=8x8x4 [512]=8x8x8)
# Mapping short names (used in point names and CSVs) and torusrt-sim arguments.
declare -A MAPARG=([block]=block [cyclic]=cyclic [bc2]=block-cyclic:2 [bc3]=block-cyclic:3)
# The cluster study: 16 clusters arranged as the flat 16 are, load-balancing mapping at the
# cluster level.
CLUSTER_NODES=16
# The readings swept, the default first: each has its own results folder RESULTS/READING with the
# same points, CSVs and plots (docs/readings.md).
#   fitted      the fit (docs/fidelity.md): --timing-profile fitted, scenes/paper-image1.nff and
#               paper-image2.nff, cyclic, 16 nodes as a ring of 16, units counted per plane,
#               memory counted 0 / 4 / 36 bytes (the machine files' settings)
#   calibrated  --timing-profile calibrated, image 1 scenes/paper-image1-planar.nff, cyclic, 4x2x2:
#               the reading before the fits
#   literal     --timing-profile literal, the planar image 1, cyclic, 4x2x2
#   round-one   the first fit: --timing-profile round-one, image 1 scenes/paper-image1-planar-z.nff,
#               block-cyclic:3, ties on even rings all the + way (--route-ties plus), 4x2x2
# Image 2 is scenes/paper-image2-floor.nff under each but the fitted.
READINGS=(fitted calibrated literal round-one)

# use_reading NAME: PROFILE, IMAGE1 and IMAGE2 (files in scenes/), the arrangement of 16, the
# load-balancing mapping and the reading's own arguments (READING_ARGS) of reading NAME; the
# TORUSRT_ variables above still win.
use_reading() {
    local shape16=4x2x2
    READING_ARGS=() IMAGE2=paper-image2-floor.nff
    case $1 in
        fitted)
            PROFILE=fitted IMAGE1=paper-image1.nff IMAGE2=paper-image2.nff MAPARG[cyclic]=cyclic shape16=16
            READING_ARGS=(--preprocess-count per-plane --cell-header-bytes 0 --list-entry-bytes 4
                          --object-record-bytes 36) ;;
        round-one)
            PROFILE=round-one IMAGE1=paper-image1-planar-z.nff MAPARG[cyclic]=block-cyclic:3
            READING_ARGS=(--route-ties plus) ;;
        calibrated|literal) PROFILE=$1 IMAGE1=paper-image1-planar.nff MAPARG[cyclic]=cyclic ;;
        *) die "the reading must be one of: ${READINGS[*]}, not '$1'" ;;
    esac
    MAPARG[cyclic]=${TORUSRT_LB_MAP:-${MAPARG[cyclic]}}
    SHAPE16=${TORUSRT_SHAPE16:-$shape16}
    SHAPE[16]=$SHAPE16 CLUSTER_SHAPE=$SHAPE16
}

# Sweep definition per mode: image size, scenes, IP counts, mappings, processors per cluster.
# define_mode full|quick
define_mode() {
    case $1 in
        full)
            SIZE=144x144
            SCENES=(image1 image2)
            NLIST=(1 2 4 8 16 32 64 128 256 512)
            read -r -a MAPS <<<"${TORUSRT_MAPS:-block cyclic bc2 bc3}"
            MLIST=(1 2 4 8 12 16 32 64)
            DATAS=(replicated shared)
            CLUSTER_SCENES=(image1 image2)
            ;;
        quick)
            SIZE=32x32
            SCENES=(image1 image2)
            NLIST=(1 4 16)
            MAPS=(block cyclic bc2)
            MLIST=(1 4 16)
            DATAS=(replicated shared)
            CLUSTER_SCENES=(image1)
            ;;
        *) die "mode must be full or quick, not '$1'" ;;
    esac
    MODE=$1
}

scene_file() {
    case $1 in
        image1) echo "${TORUSRT_SCENE_IMAGE1:-$REPO/scenes/${IMAGE1:-paper-image1.nff}}" ;;
        image2) echo "${TORUSRT_SCENE_IMAGE2:-$REPO/scenes/${IMAGE2:-paper-image2.nff}}" ;;
        *) echo "$REPO/scenes/paper-$1.nff" ;;
    esac
}

# The backend every study runs its points on (experiments/backend): set by backend_option from
# --backend local|ssh:HOSTFILE|slurm, -j N (points in flight), --slurm-args "..." and
# --per-task K (points per Slurm array task).
BACKEND=local JOBS="" SLURM_ARGS="" PER_TASK=""
BACKEND_HELP='--backend local|ssh:HOSTFILE|slurm, -j N, --slurm-args "SBATCH OPTIONS", --per-task K'

# backend_option ARGS...: takes one backend option off the front of ARGS, setting SHIFT to the
# words it used; returns 1 (and leaves everything alone) if ARGS does not start with one.
# Each takes its value as the next word or after '=' (--slurm-args=--account=foo); the value of
# --slurm-args is any number of sbatch options, quoted as one word when there are several.
backend_option() {
    case $1 in
        --backend|--slurm-args|--per-task|-j) need_value "$@" ;;
        --backend=|--slurm-args=|--per-task=) die "${1%=}: an empty value" ;;
        --backend=*|--slurm-args=*|--per-task=*) given_once "$1" ;;
        -j[0-9]*) given_once -j ;;
    esac
    SHIFT=2
    case $1 in
        --backend) BACKEND=$2 ;;
        --backend=*) BACKEND=${1#*=}; SHIFT=1 ;;
        --slurm-args) SLURM_ARGS=$2 ;;
        --slurm-args=*) SLURM_ARGS=${1#*=}; SHIFT=1 ;;
        --per-task) check_per_task "$2"; PER_TASK=$2 ;;
        --per-task=*) check_per_task "${1#*=}"; PER_TASK=${1#*=}; SHIFT=1 ;;
        -j) check_jobs -j "$2"; JOBS=$2 ;;
        -j[0-9]*) check_jobs -j "${1#-j}"; JOBS=${1#-j}; SHIFT=1 ;;
        *) return 1 ;;
    esac
}

# check_jobs OPTION VALUE: a number of points in flight is a whole number from 1 up (the backend
# caps it at the number of points to run); anything else ends the command (exit 2) naming OPTION.
check_jobs() {
    [[ $2 =~ ^[1-9][0-9]{0,8}$ ]] || die "$1 must be a whole number of points in flight, 1 or more, not '$2'"
}
# check_per_task K: --per-task's value checked before anything is made (the backend checks it too).
check_per_task() {
    [[ $1 =~ ^[1-9][0-9]{0,8}$ ]] || die "--per-task must be a whole number of points per Slurm task, 1 or more, not '$1'"
}

# run_points STATE_DIR NAME LIST...: runs the point lists (DONE-FILE<TAB>COMMAND per line, one
# list per phase, each phase after the one before) on the chosen backend; the exit status is
# 1 if a point failed. The backend runs as in_child's child, so that a stopping signal sent to
# the calling script alone stops its points too.
run_points() {
    backend_command "$@"
    in_child "${BACKEND_CMD[@]}"
}
# backend_command STATE_DIR NAME LIST...: sets BACKEND_CMD to run_points' command.
backend_command() {
    local state=$1 name=$2
    shift 2
    local opts=(--state "$state" --backend "$BACKEND" --name "$name")
    [ -z "$JOBS" ] || opts+=(-j "$JOBS")
    # one word with "=": a value that starts with a dash is still the value
    [ -z "$SLURM_ARGS" ] || opts+=("--slurm-args=$SLURM_ARGS")
    [ -z "$PER_TASK" ] || opts+=(--per-task "$PER_TASK")
    BACKEND_CMD=(python3 "$EXP/backend" run "${opts[@]}" "${RUN_POINTS_OPTS[@]}" "$@")
}
RUN_POINTS_OPTS=()
# The stopping signals: STOP_SIGNALS, in_child and stop_script (experiments/stop_signals.sh).
# shellcheck source=experiments/stop_signals.sh
source "$EXP/stop_signals.sh"

# A script's standard output or error appended to a file it reads or writes (a scene, a machine
# or timing file, a page of docs/, a file of a results folder, also through a hard link, or one
# its command line names, a folder given included): refused before anything is written (exit 2;
# stream_checks.py). A stopping signal that comes meanwhile is taken once the check has passed
# (with its message, exit 128 + N): before, the message could go into such a file.
if [ -f /dev/stdout ] || [ -f /dev/stderr ]; then
    stop_pending=""
    for stop_sig in "${STOP_SIGNALS[@]}"; do
        # shellcheck disable=SC2064  # the signal's name and number, set now
        trap "stop_pending='${stop_sig%:*} ${stop_sig#*:}'" "${stop_sig%:*}"
    done
    python3 "$EXP/output_files.py" --check-streams "$(basename "$0")" --folders "$REPO/scenes" "$REPO/machines" \
        "$REPO/timing" "$REPO/docs" "$EXP/results" "$EXP"/*/results -- "$@" || exit $?  # 2 refused, 1 out of memory
    for stop_sig in "${STOP_SIGNALS[@]}"; do
        # shellcheck disable=SC2064
        trap "stop_script ${stop_sig%:*} ${stop_sig#*:}" "${stop_sig%:*}"
    done
    unset stop_sig
    # shellcheck disable=SC2086  # NAME NUMBER
    [ -z "$stop_pending" ] || stop_script $stop_pending
fi

# check_places [--results OPTION DIR] [--page OPTION FILE]... [--images OPTION DIR]...: the
# results folder, the pages and the plots' folders a script writes, checked before anything is
# made (output_files.py check_places): none in scenes/, machines/, timing/ or experiments/ (a
# results folder there only in a results* folder), no results folder in docs/, no page or plots
# in the results folder, and no page that is a file the command line (or TORUSRT_SCENE_IMAGE1/2,
# TORUSRT_POINT_ARGS) names; exit 2 naming the option and the file.
check_places() {
    python3 "$EXP/output_files.py" --check-places "$(basename "$0")" "$REPO" "$@" -- "${SCRIPT_ARGS[@]}" \
        environment ${TORUSRT_SCENE_IMAGE1:+"$TORUSRT_SCENE_IMAGE1"} ${TORUSRT_SCENE_IMAGE2:+"$TORUSRT_SCENE_IMAGE2"} \
        "${POINT_ARGS[@]}" || exit 2
}

# merge_joblogs STATE_DIR: STATE_DIR/joblog.phase1 and joblog.phase2 (GNU parallel backends) as
# one STATE_DIR/joblog with one header, for a report's run facts.
merge_joblogs() {
    local f logs=()
    for f in "$1"/joblog.phase[12]; do [ ! -s "$f" ] || logs+=("$f"); done
    if [ ${#logs[@]} -eq 0 ]; then rm -f "$1/joblog"; return 0; fi
    { cat "${logs[0]}"; for f in "${logs[@]:1}"; do tail -n +2 "$f"; done; } | write_file "$1/joblog"
}

# A study's points as scripts any machine can run. study_script WORK "FUNCTIONS" "VARIABLES"
# writes WORK/point.sh: the study's FUNCTIONS with the VARIABLES they read (and write_file, with
# which a point writes its rows through experiments/output_files.py), running "FUNCTION
# ARG..." given on its command line. study_list WORK LIST < ARGS turns ARGS (one point per line:
# FUNCTION and its arguments, tab-separated) into the point list LIST: the point is done when
# WORK/TAG.json exists, TAG being its line with every character but letters, digits, '.' and
# '-' made '_', and its command runs WORK/point.sh with TAG in the environment. A point function
# writes its JSON as WORK/$TAG.part.json and renames it to WORK/$TAG.json when it is done.
study_script() {
    local v f
    {
        echo '#!/usr/bin/env bash'
        echo 'set -euo pipefail'
        for v in EXP $3; do declare -p "$v"; done
        for f in write_file $2; do declare -f "$f"; done
        echo '"$@"'
    } | write_file "$1/point.sh"
}
study_list() {
    local line tag words
    while IFS= read -r line; do
        [ -n "$line" ] || continue
        tag=${line//[^A-Za-z0-9.-]/_}
        IFS=$'\t' read -r -a words <<<"$line"
        printf '%s\t%s\n' "$1/$tag.json" "$(printf '%q ' "TAG=$tag" bash "$1/point.sh" "${words[@]}")"
    done | write_file "$2"
}
# study_rows LIST EXT: the files WORK/TAG.EXT of the points of LIST that have one, one after
# the other (the rows a study's points wrote beside their JSON).
study_rows() {
    local done _
    while IFS=$'\t' read -r done _; do [ ! -f "${done%.json}.$2" ] || cat "${done%.json}.$2"; done <"$1"
}

# study_args "$@": a study's command line: the backend options, --build DIR, -h, and the
# positional form [BUILD_DIR] [JOBS]; sets BUILD (absolute), SIM and JOBS.
study_args() {
    local positional=()
    while [ $# -gt 0 ]; do
        if backend_option "$@"; then shift "$SHIFT"; continue; fi
        case $1 in
            --build) need_value "$@"; BUILD=$2; shift 2 ;;
            -h|--help) show_help '^set -euo' ;;
            -*) die "unknown option '$1' (see --help)" ;;
            *) positional+=("$1"); shift ;;
        esac
    done
    [ ${#positional[@]} -le 2 ] || die "too many arguments: ${positional[*]} (see --help)"
    [ ${#positional[@]} -lt 1 ] || BUILD=${positional[0]}
    [ ${#positional[@]} -lt 2 ] || { check_jobs JOBS "${positional[1]}"; JOBS=${positional[1]}; }
    set_build "$BUILD" torusrt-render
}

# study_dirs NAME [PICTURES]: a study's folders: here (experiments/NAME), root, build, res
# (here/results), work (res/points, made) and pics (docs/PICTURES, default docs/NAME, made).
study_dirs() {
    here="$EXP/$1"
    root=$REPO
    build=$BUILD
    res="$here/results"
    work="$res/points"
    pics="$root/docs/${2:-$1}"
    mkdir -p "$work" "$pics"
}

# study_elapsed WORK START: the seconds the study has taken, this run (from START, epoch
# seconds) added to the earlier runs that kept WORK's points, so a resumed study reports its
# whole time, not the resume's (kept in WORK/elapsed_s; gone with the points).
study_elapsed() {
    local f="$1/elapsed_s" before=0
    [ ! -f "$f" ] || before=$(cat "$f")
    echo $((before + $(date +%s) - $2)) >"$f.tmp"
    mv -f "$f.tmp" "$f"
    cat "$f"
}
