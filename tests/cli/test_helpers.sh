#!/usr/bin/env bash
# The command-line tests' own helpers (common.bash): finish fails on a failed check and when no
# check ran, and passes otherwise; check counts by the command's exit status.
source "$(dirname "$0")/common.bash" "$@"
outcome() { if ( PASSED=$1 FAILED=$2; finish >/dev/null ); then echo pass; else echo fail; fi; }
check "finish with no checks fails" test "$(outcome 0 0)" = fail
check "finish with a failed check fails" test "$(outcome 3 1)" = fail
check "finish with passed checks only passes" test "$(outcome 2 0)" = pass
counted=$( PASSED=0 FAILED=0; check "true" true; check "false" false >/dev/null; echo "$PASSED $FAILED" )
check "check counts one pass and one failure ($counted)" test "$counted" = "1 1"
finish
