#!/usr/bin/env bash
# help_layout.sh - both executables' --help fits 100 columns, shows the scene as required, groups
# the options (machine with --config and --dump-config, workload, outputs, tracing, animation),
# states the number and time rules once at the top and ends with three examples. Only
# torusrt-sim, which reads machine files, says a --config file may hold its machine options,
# and its --config takes one FILE.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
for exe in torusrt-sim torusrt-render; do
    "$BUILD/$exe" --help > "$TMP/$exe.help" 2>&1
    check "$exe --help exits 0" [ $? = 0 ]
    wide=$(awk 'length($0) > 100' "$TMP/$exe.help" | wc -l)
    check "$exe --help: no line over 100 columns ($wide: $(awk 'length($0) > 100' "$TMP/$exe.help" | head -1))" [ "$wide" = 0 ]
    check "$exe --help: the scene is required in the usage" grep -q "^Usage: $exe SCENE -o FILE" "$TMP/$exe.help"
    check "$exe --help: decimal rule" grep -q "decimal" "$TMP/$exe.help"
    examples=$(awk '/^Examples:/ { on = 1; next } on && /^  / { n++ } on && /^$/ { exit } END { print n + 0 }' "$TMP/$exe.help")
    check "$exe --help: three examples ($examples)" [ "$examples" = 3 ]
    for group in "Workload:" "Outputs:" "Animation:"; do
        check "$exe --help: group $group" grep -qF "$group" "$TMP/$exe.help"
    done
done
check "torusrt-sim --help: its machine group holds what a --config file may hold" \
    grep -qx "Machine (a --config file may hold these):" "$TMP/torusrt-sim.help"
check "torusrt-sim --help: --config takes one FILE" grep -q -- "^  --config FILE  " "$TMP/torusrt-sim.help"
check "torusrt-render --help: a Machine group" grep -qx "Machine:" "$TMP/torusrt-render.help"
check "torusrt-render --help: no word of --config, which it refuses" \
    test "$(grep -c -- "--config" "$TMP/torusrt-render.help")" = 0
h="$TMP/torusrt-sim.help"
check "torusrt-sim --help: Tracing group" grep -qx "Tracing:" "$h"
check "torusrt-sim --help: the time rule once" [ "$(grep -c "bare number is seconds" "$h")" = 1 ]
# --config and --dump-config sit in the Machine group.
machine=$(awk '/^Machine/ { on = 1; next } /^[A-Z]/ { on = 0 } on' "$h")
for opt in --config --dump-config --with-timing --ips --queue --quantum; do
    check "$opt in the Machine group" grep -q -- "^  $opt " <<< "$machine"
done
# The list of names in the help comes from the names the options accept.
check "the arbiter names in the help" grep -q "round-robin or fixed-priority" "$h"
check "the dispatch names in the help" grep -q "round-robin or shortest-queue" "$h"
finish
