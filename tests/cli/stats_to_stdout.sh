#!/usr/bin/env bash
# --stats naming the command's own standard output (/dev/fd/1, as /dev/stdout) while that output
# is redirected to a regular file: the JSON is written through it, in place (never a temporary
# renamed over the device path), and with -q standard output holds exactly the JSON; without -q
# an output on standard output is refused (the summary would follow it there), by both executables,
# and so is one on standard error (warnings and notes would come before it).
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
f="$SRC/scenes/paper-image1.nff"
ok_json() { test -s "$1" && jq -e '.status == "ok"' "$1" > /dev/null; }
"$BUILD/torusrt-sim" "$f" -o "$TMP/a.png" --stats /dev/fd/1 -q --t1 1 --size 8x8 --ips 2 > "$TMP/out.json" 2> "$TMP/err"
rc=$?
check "--stats /dev/fd/1 into a file exits 0 (got $rc: $(head -1 "$TMP/err"))" test $rc -eq 0
check "--stats /dev/fd/1 into a file: stdout is the JSON report" ok_json "$TMP/out.json"
"$BUILD/torusrt-sim" "$f" -o "$TMP/b.png" --stats /dev/fd/1 -q --t1 1 --size 8x8 --ips 2 2> "$TMP/err" | cat > "$TMP/pipe.json"
check "--stats /dev/fd/1 into a pipe: stdout is the JSON report" ok_json "$TMP/pipe.json"
for exe in torusrt-sim torusrt-render; do
    "$BUILD/$exe" "$f" -o "$TMP/c.png" --stats /dev/stdout --size 8x8 > "$TMP/noq.out" 2> "$TMP/err"
    rc=$?
    check "$exe --stats /dev/stdout without -q: exit 2 (got $rc)" test $rc -eq 2
    check "$exe --stats /dev/stdout without -q: says why" grep -q "an output on standard output needs -q" "$TMP/err"
    check "$exe --stats /dev/stdout without -q: nothing written" test ! -s "$TMP/noq.out" -a ! -e "$TMP/c.png"
    # Standard error likewise: warnings and notes would come before the JSON there.
    "$BUILD/$exe" "$f" -o "$TMP/c.png" --stats /dev/stderr --size 8x8 --min-weight 2 > /dev/null 2> "$TMP/se.json"
    rc=$?
    check "$exe --stats /dev/stderr without -q: exit 2 (got $rc)" test $rc -eq 2
    check "$exe --stats /dev/stderr without -q: says why" grep -q "an output on standard error needs -q" "$TMP/se.json"
    check "$exe --stats /dev/stderr without -q: nothing written" test ! -e "$TMP/c.png"
    "$BUILD/$exe" "$f" -o "$TMP/c.png" --stats /dev/stderr --size 8x8 --min-weight 2 -q > /dev/null 2> "$TMP/se.json"
    check "$exe --stats /dev/stderr -q: standard error is the JSON alone" jq -e . "$TMP/se.json" > /dev/null
    rm -f "$TMP/c.png"
done
finish
