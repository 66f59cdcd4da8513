#!/usr/bin/env bash
# The backends of experiments/ (experiments/backend) without a cluster: the ssh backend, GNU
# parallel's --sshloginfile with its local login ':', runs a 2 x 2 sweep whose CSV equals the
# local backend's but for wall_s; a second run of the same command computes nothing; a bad
# --backend, a missing host file and a malformed point list are refused with exit 2 and a
# message naming them.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
SWEEP=$SRC/experiments/sweep scene=$SRC/scenes/paper-image2.nff
for tool in parallel gnuplot jq; do command -v $tool >/dev/null || { fail "needs $tool"; finish; exit 1; }; done
axes=(--axis ips=1,2x2 --axis map=block,cyclic)
TORUSRT_BUILD=$BUILD "$SWEEP" "$scene" "${axes[@]}" --out "$TMP/local" -j 2 -- --size 16x16 --t1 1 >"$TMP/local.out" 2>&1
check "local sweep exits 0" test $? -eq 0
echo : >"$TMP/hosts"
TORUSRT_BUILD=$BUILD "$SWEEP" "$scene" "${axes[@]}" --out "$TMP/ssh" --backend "ssh:$TMP/hosts" -j 2 \
    -- --size 16x16 --t1 1 >"$TMP/ssh.out" 2>&1
check "ssh sweep exits 0 ($(tail -n 2 "$TMP/ssh.out" | tr '\n' ' '))" test $? -eq 0
check "it ran parallel with the sshlogin file" grep -q -- "parallel .*--sshloginfile $TMP/hosts" "$TMP/ssh.out"
check "the ssh sweep's CSV equals the local one but for wall_s" diff <(nowall "$TMP/local/sweep.csv") <(nowall "$TMP/ssh/sweep.csv")
check "its joblog names the host ':'" test "$(awk -F'\t' 'NR > 1 { print $2 }' "$TMP/ssh/run/joblog.phase1" | sort -u)" = ":"
TORUSRT_BUILD=$BUILD "$SWEEP" "$scene" "${axes[@]}" --out "$TMP/ssh" --backend "ssh:$TMP/hosts" -- --size 16x16 --t1 1 \
    >"$TMP/again.out" 2>&1
check "the same command again exits 0" test $? -eq 0
check "and runs nothing" grep -q '^backend: 4 points in 1 phase(s), 4 already done, 0 to run' "$TMP/again.out"

TORUSRT_BUILD=$BUILD "$SWEEP" "$scene" "${axes[@]}" --out "$TMP/bad" --backend pbs -- --size 16x16 >"$TMP/bad.out" 2>&1
check "--backend pbs: exit 2 (got $?)" test $? -eq 2
check "--backend pbs: the message names it" grep -q -- "--backend must be local, ssh:HOSTFILE or slurm, not 'pbs'" "$TMP/bad.out"
TORUSRT_BUILD=$BUILD "$SWEEP" "$scene" "${axes[@]}" --out "$TMP/bad" --backend ssh:"$TMP/nohosts" -- --size 16x16 \
    >"$TMP/bad.out" 2>&1
check "a missing host file: exit 2 (got $?)" test $? -eq 2
check "a missing host file: named" grep -q "no such sshlogin file '$TMP/nohosts'" "$TMP/bad.out"
printf '%s\n' "relative.json	true" >"$TMP/list"
python3 "$SRC/experiments/backend" run --state "$TMP/st" "$TMP/list" >"$TMP/bad.out" 2>&1
check "a relative done file: exit 2 (got $?)" test $? -eq 2
check "a relative done file: file and line named" grep -q "$TMP/list:1: the done file must be an absolute path" "$TMP/bad.out"
check "a refused point list: no --state folder made" test ! -e "$TMP/st"
printf "%s\n" "$TMP/a.json	echo 1 >$TMP/a.json" "$TMP/b.json	exit 3" >"$TMP/list"
python3 "$SRC/experiments/backend" run --state "$TMP/st" -j 2 "$TMP/list" >"$TMP/run.out" 2>&1
check "a failing point: exit 1 (got $?)" test $? -eq 1
check "the failing point is listed with its exit status" grep -q "^backend: FAILED (exit 3 signal 0): exit 3" "$TMP/run.out"
check "and in failed.tsv" test "$(cut -f2 "$TMP/st/failed.tsv")" = "$TMP/b.json"
finish
