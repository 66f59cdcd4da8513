#!/usr/bin/env bash
# The fidelity study's first stage (study.sh --smoke --stage 1: the renderer's units at 8x8 and
# the one-processor runs at 16x16) on this machine and over ssh (GNU parallel's local login ':'):
# both choose the same scenes, counting rule and cell-step cost from the same runs, and a second
# run recomputes only the run whose JSON was removed.
source "$(dirname "$0")/common.bash" "$@"
command -v parallel >/dev/null || { fail "GNU parallel not installed"; finish; exit 1; }
study=$SRC/experiments/fidelity/study.sh
bash "$study" --smoke --stage 1 --build "$BUILD" --results "$TMP/local" -j 2 >"$TMP/local.out" 2>&1
check "local: exit 0 ($(tail -n 1 "$TMP/local.out"))" test $? -eq 0
echo : >"$TMP/hosts"
bash "$study" --smoke --stage 1 --build "$BUILD" --results "$TMP/ssh" --backend "ssh:$TMP/hosts" -j 2 >"$TMP/ssh.out" 2>&1
check "ssh: exit 0 ($(tail -n 1 "$TMP/ssh.out"))" test $? -eq 0
check "4 units runs each" test "$(find "$TMP/local/runs" "$TMP/ssh/runs" -name 'units-*.json' | wc -l)" -eq 8
check "3 one-processor runs at c = 0 each" test "$(find "$TMP/local/runs" "$TMP/ssh/runs" -name 't1-*-c0.json' | wc -l)" -eq 6
check "the same choice on both backends" test "$(grep 'stage 1 chose' "$TMP/local.out")" = \
    "$(grep 'stage 1 chose' "$TMP/ssh.out")"
same=1
# A run's figures without its wall-clock ones (wall_s, elaboration_wall_s, events_per_s, ...).
steady='walk(if type == "object" then with_entries(select(.key | test("wall|per_s") | not)) else . end)'
for j in "$TMP/local/runs"/*.json; do
    cmp -s <(jq -S "$steady" "$j" | sed "s|$TMP/local/|RES/|g") \
        <(jq -S "$steady" "$TMP/ssh/runs/$(basename "$j")" | sed "s|$TMP/ssh/|RES/|g") || same=0
done
check "every run's JSON the same on both backends, wall clock and results folder aside" test "$same" = 1
# Resume: remove one run; the rest keep their files untouched.
touch -d '2000-01-01' "$TMP/local/runs"/*.json
rm "$TMP/local/runs/units-planar-z-1-per-plane.json"
bash "$study" --smoke --stage 1 --build "$BUILD" --results "$TMP/local" -j 2 >"$TMP/again.out" 2>&1
check "resume: exit 0 ($(tail -n 1 "$TMP/again.out"))" test $? -eq 0
check "resume: the removed run is back" test -s "$TMP/local/runs/units-planar-z-1-per-plane.json"
check "resume: only that run recomputed" test "$(find "$TMP/local/runs" -name '*.json' -newer "$TMP/hosts" | wc -l)" -eq 1
check "resume: the same choice" test "$(grep 'stage 1 chose' "$TMP/again.out")" = "$(grep 'stage 1 chose' "$TMP/local.out")"
bash "$study" --smoke --stage 1 --build "$BUILD" --results "$TMP/bad" --backend pbs >"$TMP/bad.out" 2>&1
check "--backend pbs: refused" test $? -ne 0
check "--backend pbs: the message names it" grep -q "pbs" "$TMP/bad.out"
bash "$study" --stage 2 --build "$BUILD" --results "$TMP/bad2" >"$TMP/bad2.out" 2>&1
check "--stage 2: refused, naming --stage" test $? -eq 2 -a -n "$(grep -- '--stage' "$TMP/bad2.out")"
bash "$study" --stage 1 --build "$BUILD" --results "$TMP/local" >"$TMP/mixed.out" 2>&1
check "a full run in a smoke run's results folder: refused" test $? -eq 2
check "a full run in a smoke run's results folder: the message says so" grep -q "holds a smoke run's results" "$TMP/mixed.out"
finish
