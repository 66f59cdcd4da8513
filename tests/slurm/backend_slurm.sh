#!/usr/bin/env bash
# The Slurm backend against a real Slurm: a one-node Slurm (Debian's slurm-wlm and munge, all
# its files in the test's folder, in a private network namespace) runs a 4 x 2 sweep of
# experiments/sweep and the buffer study (--quick) through --backend slurm; their CSVs equal a
# local run's but for the wall-clock columns. An array task cancelled mid-way leaves its
# points failed and listed (with the task's state and output), the rest done, and the same
# command then computes only those; an interrupt (Ctrl-C) cancels the arrays. Needs root (the
# daemons run as root): without it the test says so and is skipped (exit 77). When it really
# ran it writes BUILD/slurm-test.ran, which .ci/run requires.
# Run: bash backend_slurm.sh BUILD_DIR SOURCE_DIR
rm -f "$1/slurm-test.ran"  # an earlier run's mark must not stand for this one
if [ "$(id -u)" -ne 0 ]; then
    echo "SKIP: this test needs root (it starts slurmctld, slurmd and munged)"
    exit 77
fi
for tool in slurmctld slurmd munged sbatch squeue scancel sacct parallel unshare ip gnuplot jq; do
    command -v $tool >/dev/null || { echo "SKIP: $tool is not installed (scripts/setup.sh installs it)"; exit 77; }
done
if [ -z "${TORUSRT_SLURM_NETNS:-}" ]; then  # again, in a network namespace of its own
    unshare --net true 2>/dev/null || { echo "SKIP: no private network namespace (unshare --net)"; exit 77; }
    TORUSRT_SLURM_NETNS=1 exec unshare --net bash "$0" "$@"
fi
# 127.0.0.2 beside 127.0.0.1: getaddrinfo (AI_ADDRCONFIG) wants an address other than 127.0.0.1
ip link set lo up && ip addr add 127.0.0.2/32 dev lo || { echo "FAIL: cannot set up the namespace's lo"; exit 1; }
source "$(dirname "$0")/../cli/common.bash" "$@"
source "$(dirname "$0")/single_node.bash"
trap 'slurm_stop; rm -rf "$TMP"' EXIT
start_s=$SECONDS

slurm_start "$TMP/slurm" || { fail "the one-node Slurm did not start"; finish; exit 1; }
date -u +%FT%TZ >"$BUILD/slurm-test.ran"
echo "Slurm up in $((SECONDS - start_s)) s"
SWEEP=$SRC/experiments/sweep
scene=$SRC/scenes/paper-image2.nff
axes=(--axis ips=1,2,2x2,2x2x2 --axis map=block,cyclic)
fixed=(-- --size 16x16 --t1 1)
# A stand-in simulator: the first point, ips=1, map=block, waits (two minutes) before running
# while $TMP/slow.on exists. The resumed sweep runs the same stand-in with the file gone: a
# sweep point is known by its executable too, so another executable would run every point again.
mkdir -p "$TMP/slowbuild"
touch "$TMP/slow.on"
cat >"$TMP/slowbuild/torusrt-sim" <<SIM
#!/usr/bin/env bash
# Slow for the point's run only: the sweep's dry run of its first point (--dump-config) is not.
case " \$* " in *" --dump-config "*) ;; *" --ips 1 --map block "*) [ -e "$TMP/slow.on" ] && { touch "$TMP/slow.started"; sleep 120; } ;; esac
exec "$BUILD/torusrt-sim" "\$@"
SIM
chmod +x "$TMP/slowbuild/torusrt-sim"
# at WHAT: the time since the test started, for reading where it goes.
at() { echo "$((SECONDS - start_s)) s: $*"; }
# wait_file FILE SECONDS: until FILE exists.
wait_file() { local end=$((SECONDS + $2)); while [ ! -e "$1" ] && [ $SECONDS -lt $end ]; do sleep 0.2; done; [ -e "$1" ]; }

# 1. The reference: the same sweep on this machine.
TORUSRT_BUILD=$BUILD "$SWEEP" "$scene" "${axes[@]}" --out "$TMP/local" -j 2 "${fixed[@]}" >"$TMP/local.out" 2>&1
check "local sweep exits 0 ($(tail -n 2 "$TMP/local.out" | tr '\n' ' '))" test $? -eq 0

at "the local sweep done"
# 2. On Slurm, two points per task; the slow point's task is cancelled while it runs, so
#    neither of its points is done.
set -m  # background jobs in their own process groups, as a terminal's would be
TORUSRT_BUILD=$TMP/slowbuild "$SWEEP" "$scene" "${axes[@]}" --out "$TMP/slurm" --backend slurm --per-task 2 \
    "${fixed[@]}" >"$TMP/slurm1.out" 2>&1 &
sweep_pid=$!
if wait_file "$TMP/slow.started" 90; then
    task=$(basename "$(grep -l 'ips_1-map_block' "$TMP/slurm/run/slurm/"*.out)" .out)
    check "the slow point's task is named (${task:-none})" test -n "$task"
    scancel "$task"
else
    fail "the slow point never started: $(tail -n 5 "$TMP/slurm1.out")"
fi
wait $sweep_pid
rc=$?
out=$TMP/slurm1.out
check "a cancelled task makes the sweep exit 1 (got $rc)" test $rc -eq 1
check "it printed the sbatch line it submitted" grep -q '^backend: phase 1, 8 points in 4 tasks of 2: sbatch .*--array 1-4 ' "$out"
check "it showed the progress [done/8]" grep -q '^\[8/8\]$' "$out"
check "the cancelled task is listed with its state and output" grep -q "^backend: task $task CANCELLED" "$out"
check "the points without a result are listed as failed" test "$(grep -c '^backend: FAILED .*ips_1-map_' "$out")" -eq 2
check "their CSV rows say failed" test "$(awk -F, '$1 == "1" { print $3 }' "$TMP/slurm/sweep.csv" | sort -u)" = failed
check "the other 6 points are done" test "$(ls "$TMP/slurm/points/"*.json | wc -l)" -eq 6
if [ "$FAILED" -gt 0 ]; then  # what the sweep said and left, for reading a failure
    echo "--- $out (last 25 lines):"; tail -n 25 "$out"
    echo "--- points: $(cd "$TMP/slurm/points" && ls | tr '\n' ' ')"
    echo "--- task outputs:"; tail -n 5 "$TMP/slurm/run/slurm/"*.out
fi

at "the cancelled sweep done"
# 3. The same command again (the stand-in, no longer slow) computes the two missing points only.
rm -f "$TMP/slow.on"
TORUSRT_BUILD=$TMP/slowbuild "$SWEEP" "$scene" "${axes[@]}" --out "$TMP/slurm" --backend slurm --per-task 2 \
    "${fixed[@]}" >"$TMP/slurm2.out" 2>&1
rc=$?
check "the resumed sweep exits 0 (got $rc: $(tail -n 3 "$TMP/slurm2.out" | tr '\n' ' '))" test $rc -eq 0
check "it ran only the missing points" grep -q '^backend: 8 points in 1 phase(s), 6 already done, 2 to run on Slurm' "$TMP/slurm2.out"
check "Slurm's sweep.csv equals the local one but for wall_s" \
    diff <(nowall "$TMP/local/sweep.csv") <(nowall "$TMP/slurm/sweep.csv")
check "every point ok" test "$(awk -F, 'NR > 1 && $3 != "ok"' "$TMP/slurm/sweep.csv" | wc -l)" -eq 0

at "the resumed sweep done"
# 4. An interrupt while the arrays are queued or running cancels them.
rm -f "$TMP/slow.started"
touch "$TMP/slow.on"
TORUSRT_BUILD=$TMP/slowbuild "$SWEEP" "$scene" "${axes[@]}" --out "$TMP/slurm-int" --backend slurm --per-task 1 \
    "${fixed[@]}" >"$TMP/int.out" 2>&1 &
sweep_pid=$!
wait_file "$TMP/slow.started" 90 || fail "the slow point never started (interrupt)"
kill -INT -- -$sweep_pid
wait $sweep_pid
rc=$?
check "an interrupted sweep exits non-zero (got $rc)" test $rc -ne 0
check "the interrupt cancelled the array" grep -q '^backend: interrupted: scancel [0-9]' "$TMP/int.out"
wait_for 30 sh -c '[ -z "$(squeue -h)" ]'
check "nothing left in the queue" test -z "$(squeue -h)"
set +m

at "the interrupted sweep done"
# 5. A study: the buffer study (quick) on Slurm and on this machine give the same runs.tsv.
bash "$SRC/experiments/buffers/study.sh" --quick --results "$TMP/buf-local" --build "$BUILD" -j 2 \
    >"$TMP/buf-local.out" 2>&1
check "buffer study, local: exit 0 ($(tail -n 1 "$TMP/buf-local.out"))" test $? -eq 0
at "the local buffer study done"
bash "$SRC/experiments/buffers/study.sh" --quick --results "$TMP/buf-slurm" --build "$BUILD" --backend slurm \
    --per-task 8 >"$TMP/buf-slurm.out" 2>&1
check "buffer study, Slurm: exit 0 ($(tail -n 2 "$TMP/buf-slurm.out" | tr '\n' ' '))" test $? -eq 0
check "buffer study: phase 2 submitted after phase 1 (afterany)" \
    grep -q '^backend: phase 2, 48 points in 6 tasks of 8: sbatch .*--dependency=afterany:[0-9]' "$TMP/buf-slurm.out"
check "buffer study: 48 runs" test "$(tail -n +2 "$TMP/buf-slurm/runs.tsv" | wc -l)" -eq 48
check "buffer study: Slurm's runs.tsv equals the local one" \
    diff <(nowall "$TMP/buf-local/runs.tsv" $'\t') <(nowall "$TMP/buf-slurm/runs.tsv" $'\t')
echo "slurm test: $((SECONDS - start_s)) s"
finish
