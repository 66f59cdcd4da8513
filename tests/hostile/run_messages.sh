#!/usr/bin/env bash
# run_messages.sh - the messages and statuses of runs that fail early or in the middle:
# timing-file values (an underflow named as such, a leading zero with the number to write, a
# value out of range at its line) and --timing-values with a stray comma; --help and --version
# into a full device; a frame name too long for the file system, and a path too long for its
# temporary to a file that exists, refused before the run (the path shown cut); --vcd's
# temporary folder in a TMPDIR that is not there (named); the
# memory budget running out as an animation's frame is set up (the budget message naming the
# frame, once, not SystemC's E546); a stopping signal that arrives before the program's start
# (held blocked across exec) ends the run with the message; and memory the system refuses
# (ulimit -v) while building the cell lists, the cluster's process stacks or Scotch's mapping:
# exit 1 with the out-of-memory message naming the stage and --memory-budget.
#
# Usage (CTest runs it so): bash tests/hostile/run_messages.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-render torusrt-sim
time_limit 100
f=$(source_scene paper-image1-planar-z) || exit 1
sim=("$BUILD/torusrt-sim" -q --t1 1 --size 8x8)
sim_anim=("$BUILD/torusrt-sim" -q --size 8x8)  # an animation takes no --t1
cd "$TMP" || exit 1
mkdir out

# expect_message NAME STATUS PATTERN COMMAND...: exits STATUS, standard error matches PATTERN
# (grep -E), and out/ is empty.
expect_message() {
    local name=$1 status=$2 pattern=$3
    shift 3
    rm -rf out && mkdir out
    "${run_limited[@]}" "$@" >/dev/null 2>err.txt </dev/null
    local rc=$?
    check "$name: exit $rc, expected $status: $(head -c 300 err.txt)" [ "$rc" -eq "$status" ]
    check "$name: the message: $(head -c 300 err.txt)" grep -Eq -- "$pattern" err.txt
    check "$name: nothing left: $(ls -A out | head -c 100)" [ -z "$(ls -A out)" ]
}

# Timing files and --timing-values.
printf 'link 1e-400\n' >under.timing
expect_message "timing file underflow" 1 "under.timing:1: 'link' value '1e-400' is too close to 0" \
    "${sim[@]}" "$f" -o out/a.png --timing under.timing
printf '# comment\nlink 050\n' >zero.timing
expect_message "timing file leading zero" 1 "zero.timing:2: 'link' value '050' has a leading zero.*write '50'" \
    "${sim[@]}" "$f" -o out/a.png --timing zero.timing
printf 'bus_cycle 1\n\nlink 1000001\n' >big.timing
expect_message "timing file value out of range" 1 "big.timing:3: 'link' is 1000001" \
    "${sim[@]}" "$f" -o out/a.png --timing big.timing
expect_message "--timing-values trailing comma" 2 "^torusrt-sim: --timing-values 'link=1,': an empty item" \
    "${sim[@]}" "$f" -o out/a.png --timing-values link=1,
expect_message "--timing-values leading comma" 2 "^torusrt-sim: --timing-values ',link=1': an empty item" \
    "${sim[@]}" "$f" -o out/a.png --timing-values ,link=1
expect_message "--timing-values two commas" 2 "an empty item" \
    "${sim[@]}" "$f" -o out/a.png --timing-values link=1,,bus_cycle=2

# --help and --version into a full device.
if [ -w /dev/full ]; then
    for exe in torusrt-sim torusrt-render; do
        for opt in --help --version; do
            "$BUILD/$exe" "$opt" >/dev/full 2>err.txt
            rc=$?
            check "$exe $opt >/dev/full: exit $rc, expected 1" [ "$rc" -eq 1 ]
            check "$exe $opt >/dev/full: the message: $(head -c 200 err.txt)" \
                grep -q "standard output: cannot write" err.txt
        done
    done
fi

# A frame name too long for the file system: refused before the run (exit 2), for both programs.
long=$(printf 'x%.0s' $(seq 1 260))
expect_message "sim: a 260-byte frame name" 2 "^torusrt-sim: -o 'out/${long:0:20}.*file name is too long" \
    "${sim_anim[@]}" "$f" -o "out/${long}_%d.png" --frames 2 --orbit 10
expect_message "render: a 260-byte frame name" 2 "^torusrt-render: -o 'out/${long:0:20}.*file name is too long" \
    "$BUILD/torusrt-render" -q --size 8x8 "$f" -o "out/${long}_%d.png" --frames 2 --orbit 10
expect_message "sim: a 260-byte --stats name" 2 "file name is too long" \
    "${sim[@]}" "$f" -o out/a.png --stats "out/$long.json"
# --vcd with a TMPDIR that is not there: the message names it.
expect_message "sim --vcd, TMPDIR missing" 1 "--vcd: cannot create a temporary folder in TMPDIR '$TMP/none'" \
    env TMPDIR="$TMP/none" "${sim[@]}" "$f" -o out/a.png --vcd out/a.vcd

# A path too long for its temporary (4091 bytes), to a file that exists: refused before the run
# too (exit 2), the file untouched, the path shown cut (a message of a few hundred bytes).
mkdir -p ex
for exe in torusrt-sim torusrt-render; do
    for opt in -o --stats; do
        printf 'old' >ex/x.png && printf 'old' >ex/x.json
        file=ex/x.png && [ "$opt" = --stats ] && file=ex/x.json
        long_path="ex/$(printf './%.0s' $(seq 2042))${file#ex/}"
        args=(-o ex/ok.png --stats "$long_path") && [ "$opt" = -o ] && args=(-o "$long_path")
        "${run_limited[@]}" "$BUILD/$exe" -q --size 8x8 "$f" "${args[@]}" >/dev/null 2>err.txt </dev/null
        rc=$?
        check "$exe $opt, an existing file by a 4091-byte path: exit $rc, expected 2" [ "$rc" -eq 2 ]
        check "$exe $opt, 4091 bytes: the message: $(head -c 200 err.txt)" grep -q "the path is too long" err.txt
        check "$exe $opt, 4091 bytes: the message is short ($(wc -c <err.txt) bytes)" [ "$(wc -c <err.txt)" -lt 600 ]
        check "$exe $opt, 4091 bytes: the file untouched" [ "$(cat "$file")" = old ]
        check "$exe $opt, 4091 bytes: no image" [ ! -e ex/ok.png ]
    done
done

# The packet budget running out as a frame of an animation is set up. The band of budgets where
# the first frame fits and a later one does not moves with the packet's size: the budget rises in
# 50K steps until a run is refused at a later frame (or passes), and every refusal on the way is
# one line of the budget's message, never SystemC's E546.
frame_refused=""
for kb in $(seq 16000 50 20000); do
    rm -rf out && mkdir out
    "${run_limited[@]}" "$BUILD/torusrt-sim" "$f" -q -o 'out/f%d.png' --size 256x256 --frames 3 --orbit 30 \
        --ips 2x2 --memory-budget "${kb}K" >/dev/null 2>err.txt </dev/null
    rc=$?
    if [ $rc -eq 0 ]; then break; fi
    check "budget ${kb}K: exit 1 (got $rc)" [ $rc -eq 1 ]
    check "budget ${kb}K: the budget's message" grep -q "memory budget exceeded" err.txt
    check "budget ${kb}K: no SystemC error" bash -c '! grep -q "E546\|^Error" err.txt'
    check "budget ${kb}K: one message: $(wc -l <err.txt) lines" [ "$(wc -l <err.txt)" -eq 1 ]
    if grep -qE "^torusrt-sim: frame [0-9]+: .*memory budget exceeded" err.txt; then frame_refused=$kb; break; fi
done
check "budget in an animation: some budget is refused at a later frame, named" [ -n "$frame_refused" ]

# A stopping signal pending before main (blocked by the parent across exec): the handler reports it.
for exe in torusrt-sim torusrt-render; do
    rm -rf out && mkdir out
    python3 -c 'import os, signal, sys
signal.pthread_sigmask(signal.SIG_BLOCK, [signal.SIGTERM])
os.kill(os.getpid(), signal.SIGTERM)
os.execv(sys.argv[1], sys.argv[1:])' "$BUILD/$exe" "$f" -q --size 8x8 -o out/a.png >/dev/null 2>err.txt </dev/null
    rc=$?
    check "$exe: SIGTERM pending at start: exit $rc, expected 143" [ "$rc" -eq 143 ]
    check "$exe: SIGTERM pending at start: the message: $(head -c 200 err.txt)" \
        grep -q "^$exe: stopped by SIGTERM" err.txt
    check "$exe: SIGTERM pending at start: nothing left" [ -z "$(ls -A out)" ]
done

# Memory the system refuses (ulimit -v) in the cell lists, the process stacks and Scotch.
oom() {
    local name=$1 limit=$2 stage=$3
    shift 3
    expect_message "$name" 1 "^torus[a-z-]+: out of memory while $stage.*--memory-budget" \
        bash -c 'ulimit -v "$0" && exec "$@"' "$limit" "$@"
    check "$name: no SystemC or Scotch error line alone: $(head -c 300 err.txt)" bash -c '! grep -q "^Error:" err.txt'
}
oom "sim cell lists" 120000 "loading the scene and building its cell lists" \
    "$BUILD/torusrt-sim" "$f" -q -o out/o.png --size 16x16 --cells 256 --memory-budget 0
oom "render cell lists" 120000 "loading the scene and building its cell lists" \
    "$BUILD/torusrt-render" "$f" -q -o out/o.png --size 16x16 --cells 256 --memory-budget 0
oom "cluster stacks" 150000 "building the machine \(16 nodes of 256 processors\)" \
    "$BUILD/torusrt-sim" "$f" -q -o out/o.png --size 16x16 --ips 16 --cluster 256
oom "Scotch" 300000 "mapping the cells with Scotch \(--map cost\)" \
    "$BUILD/torusrt-sim" "$f" -q -o out/o.png --size 64x64 --ips 16x16 --map cost --cells 64
finish
