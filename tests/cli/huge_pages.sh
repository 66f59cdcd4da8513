#!/usr/bin/env bash
# torusrt-sim asks glibc's allocator for transparent huge pages by running itself again with
# GLIBC_TUNABLES=glibc.malloc.hugetlb=1 when the variable is not set, and leaves a value the user
# set alone. The report says which it ran under; the second start keeps every argument (the
# outputs are where they were asked for, the image is the size asked for and the renderer's),
# and its exit status is the run's (a bad option still exits 2, with no output written).
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
need_exe torusrt-render
f=$(source_scene paper-image1) || exit 1
args=(--size 40x24 --cells 8 --ips 2x2 --t1 1 -q)
env -u GLIBC_TUNABLES "$BUILD/torusrt-sim" "$f" "${args[@]}" -o "$TMP/a.png" --stats "$TMP/a.json" ||
  fail "run without GLIBC_TUNABLES"
check "unset: the report shows the huge-page tunable" \
  test "$(json "$TMP/a.json" .allocator_tunables)" = "glibc.malloc.hugetlb=1"
check "unset: the image is the size asked for" test "$(json "$TMP/a.json" '"\(.width)x\(.height)"')" = "40x24"
GLIBC_TUNABLES=glibc.malloc.hugetlb=0 "$BUILD/torusrt-sim" "$f" "${args[@]}" -o "$TMP/b.png" --stats "$TMP/b.json" ||
  fail "run with GLIBC_TUNABLES set"
check "set: the user's value is kept" test "$(json "$TMP/b.json" .allocator_tunables)" = "glibc.malloc.hugetlb=0"
"$BUILD/torusrt-render" "$f" --size 40x24 --cells 8 -o "$TMP/r.png" -q || fail "renderer"
check "unset: the image is the renderer's" cmp -s "$TMP/a.png" "$TMP/r.png"
check "set: the image is the renderer's" cmp -s "$TMP/b.png" "$TMP/r.png"
check "both: the same simulated time" test "$(json "$TMP/a.json" .sim_time_s)" = "$(json "$TMP/b.json" .sim_time_s)"
env -u GLIBC_TUNABLES "$BUILD/torusrt-sim" "$f" "${args[@]}" --ips 0 -o "$TMP/c.png" 2> "$TMP/c.err"
check "unset, bad option: exit 2" test $? -eq 2
check "unset, bad option: the message names the option" grep -q -- "--ips" "$TMP/c.err"
check "unset, bad option: no image" test ! -e "$TMP/c.png"
finish
