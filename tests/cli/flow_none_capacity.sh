#!/usr/bin/env bash
# The statement of docs/flow-control.md: with one class (--flow none), paper-image1 on 16 IPs
# (4x2x2, the default profile, 144x144) stalls with 16, 64, 256 and 1024 packets per queue and
# finishes with 4096, under the block and the cyclic mapping; the class scheme finishes at each.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
time_limit 120
scene="$SRC/scenes/paper-image1.nff"
for map in block cyclic; do
    for q in 16 64 256 1024 4096; do
        "${run_limited[@]}" "$BUILD/torusrt-sim" "$scene" --ips 4x2x2 --map "$map" --flow none --queue "$q" \
            --t1 1 -o "$TMP/f.png" -q 2>/dev/null
        rc=$?
        want=3
        [ "$q" -eq 4096 ] && want=0
        check "$map, --flow none --queue $q: exit $want (got $rc)" test "$rc" -eq "$want"
        rm -f "$TMP/f.png"
    done
    "${run_limited[@]}" "$BUILD/torusrt-sim" "$scene" --ips 4x2x2 --map "$map" --queue 16 --t1 1 -o "$TMP/c.png" -q
    check "$map, --flow classes --queue 16 finishes" test -s "$TMP/c.png"
done
finish
