#!/usr/bin/env bash
# out_of_memory.sh - the system refusing memory (ulimit -v) while a 4096-node machine is being
# built: the run says what it was building and names --memory-budget, exits 1 (no abort), and
# leaves no output and no temporary (its VCD's and save file's, and the trace's FIFO folder), also
# when the limit falls among its modules (no abort as they are destroyed); and
# the same when memory runs out later in the run; Scotch short of memory (--map cost) and a
# --stats-interval series growing past the limit end so too, with the run's message once, and
# so do the pilots of --map cost and --load-map, and torusrt-render reading its scene.
#
# Usage (CTest runs it so): bash tests/hostile/out_of_memory.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim torusrt-render
time_limit 60
f=$(source_scene paper-image1) || exit 1
cd "$TMP" || exit 1
mkdir out tmpdir
# 150 MB of address space: the scene loads, the machine's 4096 nodes do not fit.
(TMPDIR="$TMP/tmpdir" "${run_limited[@]}" bash -c 'ulimit -v 150000 && exec "$@"' _ "$BUILD/torusrt-sim" "$f" -q --t1 1 --ips 16x16x16 \
    --size 8x8 -o out/a.png --stats out/a.json --vcd out/a.vcd >/dev/null 2>err.txt </dev/null)
rc=$?
check "4096 nodes under ulimit -v: exit $rc, expected 1: $(head -c 300 err.txt)" [ "$rc" -eq 1 ]
check "4096 nodes under ulimit -v: the message names the stage: $(head -c 300 err.txt)" \
    grep -q "^torusrt-sim: out of memory while building the machine (4096 nodes)" err.txt
check "4096 nodes under ulimit -v: the message names --memory-budget" grep -q -- "--memory-budget" err.txt
check "4096 nodes under ulimit -v: no abort message" bash -c '! grep -q "terminate called" err.txt'
check "4096 nodes under ulimit -v: nothing left: $(ls -A out; ls -A tmpdir)" \
    [ -z "$(ls -A out)$(ls -A tmpdir)" ]
# A limit too small for the libraries' own start-up (SystemC's static constructors, before main):
# exit 1 with a message (where the limit falls in the scene's reading, the one naming that
# stage), never an abort; smaller still, the system's loader refuses (127).
aborts=0 other=0
for limit in 9000 10000 11000 12000 13000 14000 15000 16000 18000 20000; do
    for args in "--version" "$f -q -o out/v.png --size 8x8"; do
        # shellcheck disable=SC2086  # the arguments split at their spaces
        ("${run_limited[@]}" bash -c 'ulimit -v "$0" && exec "$@"' "$limit" "$BUILD/torusrt-sim" $args >/dev/null \
            2>err.txt </dev/null)
        rc=$?
        if [ "$rc" -ge 128 ] || grep -q "terminate called" err.txt; then aborts=$((aborts + 1));
        elif [ "$rc" -eq 127 ] && grep -q "error while loading shared libraries" err.txt; then :;
        elif [ "$rc" -ne 0 ] && ! grep -q "^torusrt-sim: \(.*: \)\{0,1\}out of memory" err.txt; then
            other=$((other + 1))
            echo "ulimit -v $limit, $args: exit $rc: $(head -c 300 err.txt)"
        fi
    done
done
check "ulimit -v 9000..20000: runs that aborted: $aborts of 20" [ "$aborts" -eq 0 ]
check "ulimit -v 9000..20000: failed runs without the out-of-memory message: $other" [ "$other" -eq 0 ]
rm -f out/v.png
# A limit that fails one of the machine's modules half built: the modules built so far are
# destroyed with next to no memory left (SystemC's destructors allocate): exit 1 with an
# out-of-memory message (the machine's, the T(1) run's, or the scene's where the limit falls
# earlier), never "terminate called" (exit 134), over limits and runs (the address space's
# layout changes from run to run).
aborts=0 other=0
for limit in 25000 30000 35000 40000 45000 50000 55000 60000; do
    for _ in 1 2 3; do
        ("${run_limited[@]}" bash -c 'ulimit -v "$0" && exec "$@"' "$limit" "$BUILD/torusrt-sim" "$f" -q -o out/o.png \
            --size 16x16 --ips 64x64 >/dev/null 2>err.txt </dev/null)
        rc=$?
        if [ "$rc" -ge 128 ] || grep -q "terminate called" err.txt; then aborts=$((aborts + 1));
        elif [ "$rc" -ne 1 ] || ! grep -q "^torusrt-sim: .*out of memory" err.txt; then
            other=$((other + 1))
            echo "ulimit -v $limit: exit $rc: $(head -c 300 err.txt)"
        fi
    done
done
check "64x64 nodes under ulimit -v 25000..60000: runs that aborted: $aborts of 24" [ "$aborts" -eq 0 ]
check "64x64 nodes under ulimit -v 25000..60000: runs without the out-of-memory message: $other" [ "$other" -eq 0 ]
check "64x64 nodes under ulimit -v: nothing left: $(ls -A out)" [ -z "$(ls -A out)" ]
# Memory running out later in the run (here: the trace's copy thread, then the simulation): exit 0
# or 1, never an abort, and on failure nothing left, the FIFO folder included.
aborts=0 left=0
for limit in 200000 250000; do
    rm -rf out tmpdir && mkdir out tmpdir
    (TMPDIR="$TMP/tmpdir" "${run_limited[@]}" bash -c 'ulimit -v "$0" && exec "$@"' "$limit" "$BUILD/torusrt-sim" "$f" \
        -q --t1 1 --ips 16x16x16 --size 32x32 -o out/a.png --stats out/a.json --vcd out/a.vcd >/dev/null 2>err.txt \
        </dev/null)
    rc=$?
    { [ "$rc" -eq 0 ] || [ "$rc" -eq 1 ]; } && ! grep -q "terminate called" err.txt || aborts=$((aborts + 1))
    [ -z "$(ls -A tmpdir)" ] && { [ "$rc" -eq 0 ] || [ -z "$(ls -A out)" ]; } || left=$((left + 1))
done
check "ulimit -v 200000 and 250000: runs that aborted: $aborts" [ "$aborts" -eq 0 ]
check "ulimit -v 200000 and 250000: failed runs that left a file: $left" [ "$left" -eq 0 ]
# Scotch short of memory (--map cost on 48x48x48 cells): Scotch 7.0 aborts on a double free when
# one of its allocations fails, so the run asks for Scotch's room first: exit 1 with the
# mapping's message, never an abort, nothing left.
for limit in 60000 90000 120000; do
    rm -rf out && mkdir out
    ("${run_limited[@]}" bash -c 'ulimit -v "$0" && exec "$@"' "$limit" "$BUILD/torusrt-sim" "$f" -q --size 16x16 \
        --ips 4x4 --map cost --cells 48 -o out/o.png --stats out/o.json >/dev/null 2>err.txt </dev/null)
    rc=$?
    check "Scotch under ulimit -v $limit: exit $rc, expected 0 or 1: $(head -c 300 err.txt)" [ "$rc" -le 1 ]
    check "Scotch under ulimit -v $limit: no abort" bash -c '! grep -q "double free\|Aborted\|terminate called" err.txt'
    [ "$limit" -eq 90000 ] && check "Scotch under ulimit -v 90000: refused (exit $rc)" [ "$rc" -eq 1 ]
    if [ "$rc" -eq 1 ]; then
        check "Scotch under ulimit -v $limit: the message: $(head -c 300 err.txt)" \
            grep -q "out of memory while .*mapping the cells with Scotch (--map cost)" err.txt
        check "Scotch under ulimit -v $limit: nothing left" [ -z "$(ls -A out)" ]
    fi
done

# A --stats-interval series growing until the system refuses memory: the run's message, once,
# naming the stage and the series, not SystemC's raw E549 report.
rm -rf out && mkdir out
("${run_limited[@]}" bash -c 'ulimit -v 60000 && exec "$@"' _ "$BUILD/torusrt-sim" "$f" -q --size 256x256 --ips 2 \
    -o out/o.png --stats out/x.json --stats-interval 1e-5 --memory-budget 0 >/dev/null 2>err.txt </dev/null)
rc=$?
check "series under ulimit -v: exit $rc, expected 1: $(head -c 300 err.txt)" [ "$rc" -eq 1 ]
check "series under ulimit -v: the run's message: $(head -c 300 err.txt)" \
    grep -q "^torusrt-sim: out of memory while simulating the image and its --stats-interval series" err.txt
check "series under ulimit -v: said once" [ "$(grep -c "out of memory" err.txt)" -eq 1 ]
check "series under ulimit -v: no E549" bash -c '! grep -q "E549" err.txt'
check "series under ulimit -v: nothing left" [ -z "$(ls -A out)" ]

# The pilot of --map cost and of --load-map over 8 and 16 million cells (--memory-budget 0: no
# budget refuses it first): the run's message, naming the pilot and --memory-budget.
for pilot in "--map cost --cells 200 --ips 2x2" "--cells 256 --load-map out/lm.png"; do
    rm -rf out && mkdir out
    # shellcheck disable=SC2086 # the options
    ("${run_limited[@]}" bash -c 'ulimit -v 400000 && exec "$@"' _ "$BUILD/torusrt-sim" "$f" -q --t1 1 \
        --size 16x16 -o out/a.png --memory-budget 0 $pilot >/dev/null 2>err.txt </dev/null)
    rc=$?
    check "pilot under ulimit -v ($pilot): exit $rc, expected 1: $(head -c 300 err.txt)" [ "$rc" -eq 1 ]
    check "pilot under ulimit -v ($pilot): the message names the pilot: $(head -c 300 err.txt)" \
        grep -q "out of memory while running the pilot of --" err.txt
    check "pilot under ulimit -v ($pilot): the message names --memory-budget" grep -q -- "--memory-budget" err.txt
    check "pilot under ulimit -v ($pilot): nothing left" [ -z "$(ls -A out)" ]
done

# torusrt-render short of memory while it reads the scene (the limits where the parser's own
# allocation is refused): the stage and --memory-budget, never a bare "FILE:LINE: out of memory".
bare=""
for limit in $(seq 14000 250 17000); do
    rm -rf out && mkdir out
    ("${run_limited[@]}" bash -c 'ulimit -v "$0" && exec "$@"' "$limit" "$BUILD/torusrt-render" "$f" -q \
        --size 32x32 --cells 48 -o out/a.png >/dev/null 2>err.txt </dev/null)
    rc=$?
    if [ "$rc" -ne 0 ] && ! grep -q "out of memory while .*--memory-budget\|out of memory while starting" err.txt; then
        bare+=" $limit: $(head -c 120 err.txt)"
    fi
done
check "render under ulimit -v 14000..17000: messages without the stage:$bare" [ -z "$bare" ]

finish
