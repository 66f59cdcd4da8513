# common.bash - shared helpers for the command-line tests (sourced, not run).
# Usage: source "$(dirname "$0")/common.bash" "$@"   sets BUILD, SRC, TMP and the check/finish helpers.
BUILD=$(cd "$1" && pwd)
SRC=$(cd "$2" && pwd)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
PASSED=0
FAILED=0

pass() { PASSED=$((PASSED + 1)); }
fail() { FAILED=$((FAILED + 1)); echo "FAIL: $*"; }
# check DESCRIPTION COMMAND...: passes if the command succeeds.
check() { local what=$1; shift; if "$@"; then pass; else fail "$what"; fi; }
finish() { echo "$PASSED passed, $FAILED failed"; [ "$FAILED" -eq 0 ]; }
# json FILE FILTER: one value from a JSON file.
json() { jq -r "$2" "$1"; }
