#!/usr/bin/env bash
# Benchmark (not a test): fuzzes the NFF reader, grid build and a tiny render with libFuzzer
# (clang -fsanitize=fuzzer,address,undefined) for EXECS executions, then prints execs,
# execs/s and findings (inputs that crashed, leaked, timed out or ran out of memory).
#
# Usage: bash bench/fuzz.sh [EXECS] [BUILD_DIR]     (1000000; build-fuzz)
# The target is built in BUILD_DIR (not the CMake build) from src/*.c and tests/fuzz/nff_fuzz.c;
# the run is seeded from scenes/, tests/nff_bad/ and tests/fuzz/corpus/ with the keyword
# dictionary tests/fuzz/nff.dict, in one job (-jobs=1). Its working corpus and any findings
# stay in BUILD_DIR (corpus/, findings/); copy every finding into tests/fuzz/regressions/.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
execs=${1:-1000000}
build=${2:-$here/build-fuzz}
cc=${CC:-clang}
command -v "$cc" >/dev/null || { echo "fuzz.sh: $cc not found (install clang: bash scripts/setup.sh)" >&2; exit 1; }
mkdir -p "$build/corpus" "$build/findings"

echo "fuzz.sh: building $build/nff_fuzz with $cc" >&2
"$cc" -std=c11 -D_POSIX_C_SOURCE=200809L -O1 -g -fno-omit-frame-pointer \
    -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
    -I"$here/include" -I"$here/src" -I/usr/include/scotch $(pkg-config --cflags libpng) \
    "$here"/src/*.c "$here/tests/fuzz/nff_fuzz.c" \
    $(pkg-config --libs libpng) -lscotch -lscotcherr -lm -o "$build/nff_fuzz"

log="$build/fuzz.log"
before=$(find "$build/findings" -type f | wc -l)
echo "fuzz.sh: $execs executions, log in $log" >&2
set +e
(cd "$build" && ./nff_fuzz -runs="$execs" -jobs=1 -workers=1 -dict="$here/tests/fuzz/nff.dict" \
    -max_len=16384 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$build/findings/" \
    "$build/corpus" "$here/tests/fuzz/corpus" "$here/scenes" "$here/tests/nff_bad") >"$log" 2>&1
status=$?
set -e
# With -jobs the job's output goes to fuzz-0.log in the build folder: add it to the log.
if [ -f "$build/fuzz-0.log" ]; then cat "$build/fuzz-0.log" >>"$log"; rm -f "$build/fuzz-0.log"; fi
after=$(find "$build/findings" -type f | wc -l)
stat() { awk -v k="stat::$1:" '$1 == k { v = $2 } END { print v + 0 }' "$log"; }
printf '%-12s %14s %12s %10s %12s\n' target execs execs_per_s findings exit_status
printf '%-12s %14d %12d %10d %12d\n' nff_fuzz "$(stat number_of_executed_units)" \
    "$(stat average_exec_per_sec)" "$((after - before))" "$status"
if [ "$after" -gt "$before" ]; then
    echo "findings (add each to tests/fuzz/regressions/):" >&2
    find "$build/findings" -type f -newer "$build/nff_fuzz" >&2
fi
