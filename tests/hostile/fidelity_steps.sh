#!/usr/bin/env bash
# fidelity_steps.sh - the fidelity study stops at a failed step of its own: a tree without the
# timing profiles it writes its timing files from (timing/) ends the study with a non-zero exit
# status before any point with a timing file runs, and leaves no empty timing file behind to be
# taken as done.
#
# Usage (CTest runs it so): bash tests/hostile/fidelity_steps.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim torusrt-render torusrt-genscenes
for tool in python3 parallel gnuplot jq; do
    command -v "$tool" >/dev/null || { echo "$TEST_NAME: $tool is not installed; skipped"; exit 77; }
done
time_limit 120
cd "$TMP" || exit 1
mkdir tree
cp -r "$SRC/experiments" "$SRC/scenes" "$SRC/machines" tree/
ln -s "$BUILD" tree/build
"${run_limited[@]}" bash tree/experiments/fidelity/study.sh --smoke --stage 1 --results "$TMP/res" -j 1 \
    --build "$BUILD" >out.txt 2>err.txt </dev/null
rc=$?
check "no timing/: exit $rc, expected a failure: $(tail -n 3 err.txt | tr '\n' ' ' | head -c 300)" [ "$rc" -ne 0 ]
check "no timing/: the message names the missing profile" grep -q "timing/calibrated.timing" err.txt
empty=$(find "$TMP/res" -name '*.timing' -size 0 2>/dev/null | tr '\n' ' ')
check "no timing/: no empty timing file left: $empty" [ -z "$empty" ]
# (the unit counts run first: they take no timing file)
points=$(find "$TMP/res" -name '*.json' ! -name 'units-*' 2>/dev/null | wc -l)
check "no timing/: no point with a timing file ran ($points JSONs)" [ "$points" -eq 0 ]
finish
