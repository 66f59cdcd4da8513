#!/usr/bin/env bash
# signals.sh - SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM and SIGPIPE in the
# middle of a run: the program says which signal stopped it, exits 128 + the signal's number and
# leaves nothing behind: no temporary beside its outputs (a VCD being written, the frames of an
# animation so far) and no trace FIFO folder in $TMPDIR, wherever in the run the signal lands. A
# reader that closes its pipe (head) stops the run the same way (SIGPIPE), or with exit 1 and the
# system's words when SIGPIPE is ignored; a summary that cannot be written is exit 1 too.
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
    check "$name: the message names SIG$sig: $(head -c 200 "$TMP/$name.err")" \
        grep -q "^$(basename "$1"): stopped by SIG$sig" "$TMP/$name.err"
    check "$name: left in the output folder: $(ls -A "$TMP/out" | head -c 200)" [ -z "$(ls -A "$TMP/out")" ]
    check "$name: left in TMPDIR: $(ls -A "$TMP/tmpdir" | head -c 200)" [ -z "$(ls -A "$TMP/tmpdir")" ]
}

sim_vcd=("$BUILD/torusrt-sim" "$f" -q --t1 1 --ips 4x4 --size 160x160 -o "$TMP/out/a.png" --stats "$TMP/out/a.json"
         --vcd "$TMP/out/a.vcd")
for sig in INT TERM HUP QUIT USR1 USR2 ALRM PIPE; do
    stopped "sim --vcd, SIG$sig" "$sig" "$TMP/tmpdir/torusrt-vcd.*" "${sim_vcd[@]}"
done
# An animation: every frame written so far is a temporary.
render_frames=("$BUILD/torusrt-render" "$f" -q --size 48x48 --frames 2000 --orbit 360 -o "$TMP/out/f%04d.png"
               --stats "$TMP/out/s.json")
stopped "render frames, SIGTERM" TERM "$TMP/out/.f0001.png.*" "${render_frames[@]}"
stopped "render frames, SIGINT" INT "$TMP/out/.f0001.png.*" "${render_frames[@]}"
stopped "render frames, SIGUSR1" USR1 "$TMP/out/.f0001.png.*" "${render_frames[@]}"
stopped "render frames, SIGALRM" ALRM "$TMP/out/.f0001.png.*" "${render_frames[@]}"
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

# A reader that closes the pipe before the run writes to it (head -n 0 reads nothing): SIGPIPE
# ends the run as any stopping signal (exit 141), or, when this shell was started with SIGPIPE
# ignored (the program inherits that), the failed write does (exit 1, "Broken pipe").
pipe_ignored=$(((0x$(awk '/^SigIgn/ {print $2}' /proc/$$/status) >> 12) & 1))
# closed_pipe NAME IGNORE COMMAND...: runs COMMAND | head -n 0 (with SIGPIPE ignored if IGNORE
# is 1) and checks the status, the message and that nothing is left in out/ and $TMPDIR.
closed_pipe() {
    local name=$1 ignore=$2
    shift 2
    rm -rf "$TMP/out" "$TMP/tmpdir" && mkdir "$TMP/out" "$TMP/tmpdir"
    if [ "$ignore" = 1 ]; then
        (trap '' PIPE && TMPDIR="$TMP/tmpdir" exec "$@" 2>"$TMP/pipe.err" </dev/null) | head -n 0
    else
        TMPDIR="$TMP/tmpdir" "$@" 2>"$TMP/pipe.err" </dev/null | head -n 0
    fi
    local rc=${PIPESTATUS[0]} want=141 words="stopped by SIGPIPE"
    if [ "$ignore" = 1 ] || [ "$pipe_ignored" = 1 ]; then want=1 words="cannot write: Broken pipe"; fi
    check "$name: exit $rc, expected $want: $(head -c 200 "$TMP/pipe.err")" [ "$rc" -eq "$want" ]
    check "$name: the message says '$words': $(head -c 200 "$TMP/pipe.err")" grep -q "$words" "$TMP/pipe.err"
    check "$name: left in the output folder: $(ls -A "$TMP/out" | head -c 200)" [ -z "$(ls -A "$TMP/out")" ]
    check "$name: left in TMPDIR: $(ls -A "$TMP/tmpdir" | head -c 200)" [ -z "$(ls -A "$TMP/tmpdir")" ]
}
sim_pipe=("$BUILD/torusrt-sim" "$f" -q --t1 1 --ips 4x4 --size 64x64 -o "$TMP/out/a.png")
closed_pipe "sim --stats /dev/stdout | head, with --vcd" 0 "${sim_pipe[@]}" --stats /dev/stdout --vcd "$TMP/out/a.vcd"
closed_pipe "sim --vcd /dev/stdout | head" 0 "${sim_pipe[@]}" --stats "$TMP/out/a.json" --vcd /dev/stdout
closed_pipe "render --stats /dev/stdout | head" 0 "$BUILD/torusrt-render" "$f" -q --size 64x64 -o "$TMP/out/a.png" \
    --stats /dev/stdout
closed_pipe "sim --stats /dev/stdout | head, SIGPIPE ignored" 1 "${sim_pipe[@]}" --stats /dev/stdout \
    --vcd "$TMP/out/a.vcd"
# The summary alone on the closed pipe, SIGPIPE ignored: the files are written, but the run says
# its summary was lost (exit 1), as it does on a full device.
rm -rf "$TMP/out" && mkdir "$TMP/out"
(trap '' PIPE && exec "$BUILD/torusrt-sim" "$f" --t1 1 --ips 2 --size 16x16 -o "$TMP/out/a.png" 2>"$TMP/sum.err" \
    </dev/null) | head -n 0
rc=${PIPESTATUS[0]}
check "sim summary | head, SIGPIPE ignored: exit $rc, expected 1: $(head -c 200 "$TMP/sum.err")" [ "$rc" -eq 1 ]
check "sim summary | head, SIGPIPE ignored: the message names standard output" \
    grep -q "standard output: cannot write: Broken pipe" "$TMP/sum.err"
"$BUILD/torusrt-sim" "$f" --t1 1 --ips 2 --size 16x16 -o "$TMP/out/a.png" >/dev/full 2>"$TMP/sum.err" </dev/null
rc=$?
check "sim summary > /dev/full: exit $rc, expected 1: $(head -c 200 "$TMP/sum.err")" [ "$rc" -eq 1 ]
check "sim summary > /dev/full: the message names standard output" \
    grep -q "standard output: cannot write: No space left on device" "$TMP/sum.err"
finish
