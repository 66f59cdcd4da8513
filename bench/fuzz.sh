#!/usr/bin/env bash
# Benchmark (not a test): fuzzes every reader of user files with libFuzzer
# (clang -fsanitize=fuzzer,address,undefined), EXECS executions per target, then prints each
# target's execs, execs/s and findings (inputs that crashed, leaked, timed out or ran out of
# memory). The targets (tests/fuzz/):
#   nff_fuzz      the NFF reader, grid build and a tiny render; seeds scenes/, tests/nff_bad/,
#                 tests/fuzz/corpus/; dictionary nff.dict
#   map_fuzz      the map-file reader (rt_map_file_parse); seeds tests/fuzz/map_corpus/; map.dict
#   motion_fuzz   the motion-file reader (rt_motion_parse), the object space and the cell-list
#                 update; seeds tests/fuzz/motion_corpus/; motion.dict
#   machine_fuzz  the machine-file reader (MachineFileReader); seeds tests/fuzz/machine_corpus/;
#                 machine.dict
#
# Usage: bash bench/fuzz.sh [EXECS] [BUILD_DIR] [TARGET...]   (1000000; build-fuzz; all four)
# The targets are built in BUILD_DIR (not the CMake build), each run in one job (-jobs=1). Its
# working corpus and any findings stay in BUILD_DIR (corpus-TARGET/, findings-TARGET/); copy
# every finding into tests/fuzz/regressions/.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
execs=${1:-1000000}
build=${2:-$here/build-fuzz}
shift $(($# > 2 ? 2 : $#))
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(nff_fuzz map_fuzz motion_fuzz machine_fuzz)
cc=${CC:-clang}
cxx=${CXX:-clang++}
command -v "$cc" >/dev/null || { echo "fuzz.sh: $cc not found (install clang: bash scripts/setup.sh)" >&2; exit 1; }
mkdir -p "$build"
sanitize=(-O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined)
kernel=(-std=c11 -D_POSIX_C_SOURCE=200809L -I"$here/include" -I"$here/src" -I/usr/include/scotch
        $(pkg-config --cflags libpng))

libs=($(pkg-config --libs libpng) -lscotch -lscotcherr -lm)

# The kernel (src/*.c), compiled once for every target into BUILD_DIR/kernel/.
build_kernel() {
    mkdir -p "$build/kernel"
    echo "fuzz.sh: building the kernel in $build/kernel" >&2
    local c
    for c in "$here"/src/*.c; do
        "$cc" "${kernel[@]}" "${sanitize[@]/-fsanitize=fuzzer,/-fsanitize=fuzzer-no-link,}" -c "$c" \
            -o "$build/kernel/$(basename "$c" .c).o"
    done
}

build_target() {  # NAME: compiles BUILD_DIR/NAME
    local name=$1
    echo "fuzz.sh: building $build/$name" >&2
    case $name in
    nff_fuzz | map_fuzz | motion_fuzz)
        "$cc" "${kernel[@]}" "${sanitize[@]}" "$here/tests/fuzz/$name.c" "$build"/kernel/*.o "${libs[@]}" \
            -o "$build/$name" ;;
    machine_fuzz)
        "$cxx" -std=c++17 "${sanitize[@]}" -I"$here/support" -I"$here/testbench/common" -I"$here/include" \
            "$here"/testbench/common/machine_file_reader.cpp "$here"/support/{option_parsing,option_spec}.cpp \
            "$here/tests/fuzz/machine_fuzz.cpp" "$build"/kernel/*.o "${libs[@]}" \
            $(pkg-config --cflags --libs tomlplusplus) -o "$build/$name" ;;
    *) echo "fuzz.sh: no target $name" >&2; exit 2 ;;
    esac
}

# run_target NAME DICT MAX_LEN SEED_FOLDER...: one libFuzzer run; prints its table row.
run_target() {
    local name=$1 dict=$2 max_len=$3
    shift 3
    local log="$build/$name.log" corpus="$build/corpus-$name" findings="$build/findings-$name"
    mkdir -p "$corpus" "$findings"
    local before after status
    before=$(find "$findings" -type f | wc -l)
    echo "fuzz.sh: $name: $execs executions, log in $log" >&2
    set +e
    (cd "$build" && "./$name" -runs="$execs" -jobs=1 -workers=1 -dict="$dict" -max_len="$max_len" -timeout=10 \
        -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$findings/" "$corpus" "$@") >"$log" 2>&1
    status=$?
    set -e
    # With -jobs the job's output goes to fuzz-0.log in the build folder: add it to the log.
    if [ -f "$build/fuzz-0.log" ]; then cat "$build/fuzz-0.log" >>"$log"; rm -f "$build/fuzz-0.log"; fi
    after=$(find "$findings" -type f | wc -l)
    stat() { awk -v k="stat::$1:" '$1 == k { v = $2 } END { print v + 0 }' "$log"; }
    printf '%-12s %14d %12d %10d %12d\n' "$name" "$(stat number_of_executed_units)" \
        "$(stat average_exec_per_sec)" "$((after - before))" "$status"
    if [ "$after" -gt "$before" ]; then
        echo "findings of $name (add each to tests/fuzz/regressions/):" >&2
        find "$findings" -type f -newer "$build/$name" >&2
    fi
}

build_kernel
for t in "${targets[@]}"; do build_target "$t"; done
printf '%-12s %14s %12s %10s %12s\n' target execs execs_per_s findings exit_status
for t in "${targets[@]}"; do
    case $t in
    nff_fuzz) run_target nff_fuzz "$here/tests/fuzz/nff.dict" 16384 "$here/tests/fuzz/corpus" "$here/scenes" \
        "$here/tests/nff_bad" ;;
    map_fuzz) run_target map_fuzz "$here/tests/fuzz/map.dict" 4096 "$here/tests/fuzz/map_corpus" ;;
    motion_fuzz) run_target motion_fuzz "$here/tests/fuzz/motion.dict" 4096 "$here/tests/fuzz/motion_corpus" ;;
    machine_fuzz) run_target machine_fuzz "$here/tests/fuzz/machine.dict" 4096 "$here/tests/fuzz/machine_corpus" ;;
    esac
done
