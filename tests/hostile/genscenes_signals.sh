#!/usr/bin/env bash
# genscenes_signals.sh - torusrt-genscenes ends on the stopping signals as the other executables
# do: a signal that is pending when it starts (held blocked across its exec) is taken at once, with
# `torusrt-genscenes: stopped by SIGNAME` and 128 + the signal's number, and nothing written; and
# INT or TERM at 20 moments spread over a run (one takes some tens of ms) leaves no temporary
# `.NAME.nff.XXXXXX` behind, only whole scenes (each one that is there equals a full run's).
#
# Usage (CTest runs it so): bash tests/hostile/genscenes_signals.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-genscenes
command -v python3 >/dev/null || { echo "$TEST_NAME: python3 is not installed; skipped"; exit 77; }
gen=$BUILD/torusrt-genscenes
set -m  # background runs get SIGINT as a foreground run would (not ignored)
"$gen" "$TMP/full" >/dev/null 2>&1 || { mkdir -p "$TMP/full" && "$gen" "$TMP/full" >/dev/null; }

# pending SIGNAL: genscenes started with SIGNAL blocked and already sent to it.
pending() {
    python3 - "$gen" "$TMP/p$1" "$1" 2>"$TMP/p$1.err" <<'PY'
import os, signal, subprocess, sys
gen, out, name = sys.argv[1:]
number = getattr(signal, "SIG" + name)
os.mkdir(out)
def start():
    signal.pthread_sigmask(signal.SIG_BLOCK, [number])
    os.kill(os.getpid(), number)  # pending across the exec
done = subprocess.run([gen, out], preexec_fn=start, stdout=subprocess.DEVNULL)
sys.exit(done.returncode if done.returncode >= 0 else 200)
PY
}
for sig in INT TERM HUP QUIT USR1 USR2 ALRM; do
    pending "$sig"
    rc=$? want=$((128 + $(kill -l "$sig")))
    check "pending SIG$sig: exit $rc, expected $want: $(head -c 200 "$TMP/p$sig.err")" [ "$rc" -eq "$want" ]
    check "pending SIG$sig: the message: $(head -c 200 "$TMP/p$sig.err")" \
        grep -qx "torusrt-genscenes: stopped by SIG$sig" "$TMP/p$sig.err"
    check "pending SIG$sig: written: $(ls -A "$TMP/p$sig" | head -c 200)" [ -z "$(ls -A "$TMP/p$sig")" ]
done

# INT and TERM at 20 moments each: no temporary stays, and every scene written is whole.
left="" partial=""
for sig in INT TERM; do
    for ((i = 0; i < 20; i++)); do
        rm -rf "$TMP/out" && mkdir "$TMP/out"
        # without the EXIT trap: a signal before the exec must not remove $TMP
        (trap - EXIT && exec "$gen" "$TMP/out" >/dev/null 2>"$TMP/moment.err" </dev/null) &
        pid=$!
        sleep "0.0$((i / 2))$((i % 2 * 5))"
        kill "-$sig" "$pid" 2>/dev/null
        wait "$pid" 2>/dev/null
        rc=$?
        [ -z "$(ls -A "$TMP/out" | grep '^\.')" ] || left+=" $sig@$i"
        for f in "$TMP/out"/*; do
            [ -e "$f" ] || continue
            cmp -s "$f" "$TMP/full/${f##*/}" || partial+=" $sig@$i:${f##*/}"
        done
        if [ "$rc" -ne 0 ]; then
            check "SIG$sig at moment $i: exit $rc: $(head -c 200 "$TMP/moment.err")" \
                [ "$rc" -eq $((128 + $(kill -l "$sig"))) ]
        fi
    done
done
check "runs that left a temporary:$left" [ -z "$left" ]
check "scenes that differ from a full run's:$partial" [ -z "$partial" ]
finish
