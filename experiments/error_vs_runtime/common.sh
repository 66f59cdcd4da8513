# shellcheck shell=bash
# common.sh - shared by the error-against-run-time study scripts (sourced, not run).
# Sets EVR_DIR (this folder), REPO (the source tree) and BUILD (the build folder: the --build
# option of the calling script, else $TORUSRT_BUILD, else REPO/build), and provides helpers.

EVR_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO=$(cd "$EVR_DIR/../.." && pwd)
BUILD=${TORUSRT_BUILD:-$REPO/build}

die() { echo "${0##*/}: $*" >&2; exit 2; }

# need_tools: the executables a study needs, with a hint where they come from.
need_build() {
  [ -x "$BUILD/torusrt-sim" ] && [ -x "$BUILD/torusrt-render" ] ||
    die "no torusrt-sim/torusrt-render in $BUILD (build them, or pass --build DIR / set TORUSRT_BUILD)"
  command -v jq >/dev/null || die "jq is needed (scripts/setup.sh installs it)"
}

# png_compare_tool: prints the path of the PNG comparison tool, building it (once, atomically,
# so concurrent callers do not clash) into BUILD/error_vs_runtime/ when missing or stale.
png_compare_tool() {
  local dir="$BUILD/error_vs_runtime" src="$EVR_DIR/png_compare.cpp"
  local exe="$dir/png_compare"
  if [ ! -x "$exe" ] || [ "$src" -nt "$exe" ]; then
    mkdir -p "$dir" || return 1
    local tmp="$exe.$$.tmp"
    # shellcheck disable=SC2046
    g++ -O2 -std=c++17 "$src" -o "$tmp" $(pkg-config --cflags --libs libpng) || { rm -f "$tmp"; return 1; }
    mv -f "$tmp" "$exe"
  fi
  echo "$exe"
}

# quantum_seconds Q: a quantum with a unit (0, 10us, 3ms, 1s, 500ns) in seconds.
quantum_seconds() {
  awk -v q="$1" 'BEGIN {
    if (q == "0") { print 0; exit }
    if (!match(q, /^[0-9.]+(e[-+]?[0-9]+)?/)) { print "bad"; exit 1 }
    v = substr(q, 1, RLENGTH) + 0; u = substr(q, RLENGTH + 1)
    f = (u == "s") ? 1 : (u == "ms") ? 1e-3 : (u == "us") ? 1e-6 : (u == "ns") ? 1e-9 : (u == "ps") ? 1e-12 : -1
    if (f < 0) { print "bad"; exit 1 }
    printf "%.12g\n", v * f }'
}

# median V...: the median of numbers.
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else printf "%.9g\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# ip_count 4x2x2 -> 16
ip_count() { echo "$1" | awk -F'x' '{ n = 1; for (i = 1; i <= NF; i++) n *= $i; print n }'; }

# fastest V...: the smallest of numbers (the wall time least disturbed by other load).
fastest() { printf '%s\n' "$@" | sort -g | head -n 1; }
