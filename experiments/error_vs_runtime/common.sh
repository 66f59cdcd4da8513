# shellcheck shell=bash
# common.sh - shared by the error-against-run-time study scripts (sourced, not run).
# Sets EVR_DIR (this folder), REPO (the source tree) and BUILD (the build folder: the --build
# option of the calling script, else $TORUSRT_BUILD, else REPO/build), and provides helpers.

EVR_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO=$(cd "$EVR_DIR/../.." && pwd)
# write_file FILE [OPTION] < TEXT: FILE written through experiments/output_files.py (atomic, never over an input).
write_file() { python3 "$REPO/experiments/output_files.py" "$@"; }
BUILD=${TORUSRT_BUILD:-$REPO/build}

die() { echo "${0##*/}: $*" >&2; exit 2; }

# need_build: the --out CSV is not one of the scenes the runs read, and the executables a study
# needs are there (with a hint where they come from).
need_build() {
  local s F
  for s in $SCENES; do  # the CSV never replaces a scene the runs read (also through a link)
    F=$(scene_file "$s")
    [ ! -e "$OUT" ] || [ ! "$OUT" -ef "$F" ] || die "--out '$OUT': is the scene file $F, an input"
  done
  [ -x "$BUILD/torusrt-sim" ] && [ -x "$BUILD/torusrt-render" ] ||
    die "no torusrt-sim/torusrt-render in $BUILD (build them, or pass --build DIR / set TORUSRT_BUILD)"
  command -v jq >/dev/null || die "jq is needed (scripts/setup.sh installs it)"
}

# png_compare_tool: prints the path of the PNG comparison tool (the CMake target png_compare).
png_compare_tool() {
  local exe="$BUILD/png_compare"
  if [ ! -x "$exe" ]; then
    echo "error_vs_runtime: no $exe (build the png_compare target: cmake --build $BUILD --target png_compare)" >&2
    return 1
  fi
  echo "$exe"
}

# median V...: the median of numbers.
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else printf "%.9g\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# ip_count 4x2x2 -> 16
ip_count() { echo "$1" | awk -F'x' '{ n = 1; for (i = 1; i <= NF; i++) n *= $i; print n }'; }

# fastest V...: the smallest of numbers (the wall time least disturbed by other load).
fastest() { printf '%s\n' "$@" | sort -g | head -n 1; }

# The helpers below serve the sweep scripts (quantum.sh, pruning.sh).

# need_value OPTION ARGS...: dies (exit 2) naming OPTION when ARGS (the words after it) are none
# or start with an empty word: an empty value is never taken as the default; or when OPTION was
# given before: the last one does not silently win.
declare -A GIVEN_OPTIONS=()
need_value() {
  [ $# -ge 2 ] || die "$1 needs a value"
  [ -n "$2" ] || die "$1: an empty value"
  [ -z "${GIVEN_OPTIONS[$1]:-}" ] || die "$1: given 2 times; give it once"
  GIVEN_OPTIONS[$1]=1
}

# study_option ARGS...: the option at ARGS that every sweep takes (--build, --out, --scenes, --ips,
# --size, --reps, -h/--help); sets SHIFT to the number of words it used; dies on any other option.
# shellcheck disable=SC2034 # the variables are the calling script's
study_option() {
  SHIFT=2
  case $1 in
    --build|--out|--scenes|--ips|--size|--reps) need_value "$@" ;;
  esac
  case $1 in
    --build) BUILD=$2 ;;
    --out) OUT=$2 ;;
    --scenes) SCENES=$2 ;;
    --ips) IPS=$2 ;;
    --size) SIZE=$2 ;;
    --reps) REPS=$2 ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown option $1 (see --help)" ;;
  esac
}

# scene_file S: S if it is a file, else REPO/scenes/S.nff.
scene_file() { if [ -f "$1" ]; then echo "$1"; else echo "$REPO/scenes/$1.nff"; fi; }
# scene_name FILE: the file's name without folder and .nff.
scene_name() { local b=${1##*/}; echo "${b%.nff}"; }

# csv_start HEADER: makes TMP (removed on exit) and OUT's folder, and starts CSV ($TMP/out.csv)
# with the HEADER line; csv_finish puts it at OUT.
csv_start() {
  TMP=$(mktemp -d)
  trap 'rm -rf "$TMP"' EXIT
  mkdir -p "$(dirname "$OUT")"
  CSV=$TMP/out.csv
  echo "$1" > "$CSV"
}
csv_finish() {
  write_file "$OUT" "--out" <"$CSV"
  echo "$(basename "$0" .sh): wrote $OUT" >&2
}

# timed_runs TAG PROGRAM ARGS...: REPS runs of BUILD/PROGRAM on the scene F at SIZE; leaves
# TAG.png and TAG.json (first run) in TMP and sets M_WALL, M_SIM_WALL (the fastest wall_s and
# sim_wall_s, which is wall_s for torusrt-render) and M_DET (true when every run gave the same
# sim_time_s).
# shellcheck disable=SC2034 # the variables are the calling script's
timed_runs() {
  local tag=$1 prog=$2; shift 2
  local walls=() simwalls=() times=() r
  for ((r = 0; r < REPS; r++)); do
    "$BUILD/$prog" "$F" -o "$TMP/$tag.$r.png" --stats "$TMP/$tag.$r.json" -q --size "$SIZE" "$@" ||
      die "$prog failed: $F $*"
    walls+=("$(jq -r .wall_s "$TMP/$tag.$r.json")")
    simwalls+=("$(jq -r '.sim_wall_s // .wall_s' "$TMP/$tag.$r.json")")
    times+=("$(jq -r .sim_time_s "$TMP/$tag.$r.json")")
  done
  M_WALL=$(fastest "${walls[@]}")
  M_SIM_WALL=$(fastest "${simwalls[@]}")
  M_DET=true
  [ "$(printf '%s\n' "${times[@]}" | sort -u | wc -l)" -eq 1 ] || M_DET=false
  mv "$TMP/$tag.0.json" "$TMP/$tag.json"
  mv "$TMP/$tag.0.png" "$TMP/$tag.png"
  rm -f "$TMP/$tag".[0-9]*.png "$TMP/$tag".[0-9]*.json
}
