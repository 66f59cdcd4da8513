#!/usr/bin/env bash
# signals.sh - SIGINT, SIGTERM and SIGHUP in the middle of a run: the program exits 128 + the
# signal's number and leaves nothing behind: no temporary beside its outputs (a VCD being
# written, the frames of an animation so far) and no trace FIFO folder in $TMPDIR, wherever in
# the run the signal lands.
#
# Usage (CTest runs it so): bash tests/hostile/signals.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-render torusrt-sim
f=$(source_scene paper-image2) || exit 1
set -m  # background runs get SIGINT as a foreground run would (not ignored)

# wait_for GLOB...: waits (up to 60 s) until one of the globs matches a file; 1 if none did.
wait_for() {
    local i
    for ((i = 0; i < 1200; i++)); do
        compgen -G "$1" >/dev/null && return 0
        sleep 0.05
    done
    return 1
}

# stopped NAME SIGNAL READY_GLOB COMMAND...: starts the run, sends SIGNAL once READY_GLOB
# exists, and checks the exit status and that out/ and the run's $TMPDIR are left empty.
stopped() {
    local name=$1 sig=$2 ready=$3
    shift 3
    rm -rf "$TMP/out" "$TMP/tmpdir" && mkdir "$TMP/out" "$TMP/tmpdir"
    TMPDIR="$TMP/tmpdir" "$@" >/dev/null 2>"$TMP/$name.err" </dev/null &
    local pid=$!
    if ! wait_for "$ready"; then
        kill -KILL "$pid" 2>/dev/null
        wait "$pid" 2>/dev/null
        fail "$name: $ready never appeared: $(head -c 200 "$TMP/$name.err")"
        return
    fi
    sleep 0.3  # into the run proper
    kill "-$sig" "$pid"
    wait "$pid"
    local rc=$? want=$((128 + $(kill -l "$sig")))
    check "$name: exit $rc, expected $want: $(head -c 200 "$TMP/$name.err")" [ "$rc" -eq "$want" ]
    check "$name: left in the output folder: $(ls -A "$TMP/out" | head -c 200)" [ -z "$(ls -A "$TMP/out")" ]
    check "$name: left in TMPDIR: $(ls -A "$TMP/tmpdir" | head -c 200)" [ -z "$(ls -A "$TMP/tmpdir")" ]
}

sim_vcd=("$BUILD/torusrt-sim" "$f" -q --t1 1 --ips 4x4 --size 160x160 -o "$TMP/out/a.png" --stats "$TMP/out/a.json"
         --vcd "$TMP/out/a.vcd")
for sig in INT TERM HUP; do
    stopped "sim --vcd, SIG$sig" "$sig" "$TMP/tmpdir/torusrt-vcd.*" "${sim_vcd[@]}"
done
# An animation: every frame written so far is a temporary.
render_frames=("$BUILD/torusrt-render" "$f" -q --size 48x48 --frames 2000 --orbit 360 -o "$TMP/out/f%04d.png"
               --stats "$TMP/out/s.json")
stopped "render frames, SIGTERM" TERM "$TMP/out/.f0001.png.*" "${render_frames[@]}"
stopped "render frames, SIGINT" INT "$TMP/out/.f0001.png.*" "${render_frames[@]}"
# The same at 20 moments spread over the run: a signal that lands while a frame's temporary is
# being made must not leave it behind (it is made and registered with the signals blocked).
left=0
for ((i = 0; i < 20; i++)); do
    rm -rf "$TMP/out" && mkdir "$TMP/out"
    "${render_frames[@]}" >/dev/null 2>&1 </dev/null &
    pid=$!
    sleep "0.$((i % 10))$((i / 10))5"
    kill -INT "$pid" 2>/dev/null
    wait "$pid"
    [ -z "$(ls -A "$TMP/out")" ] || left=$((left + 1))
done
check "render frames, SIGINT at 20 moments: runs that left a file: $left" [ "$left" -eq 0 ]
finish
