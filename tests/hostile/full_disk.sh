#!/usr/bin/env bash
# full_disk.sh - outputs on device nodes and on a full disk, in a private mount namespace
# (unshare -m) with its own tmpfs and device nodes, never the real /dev: a device named by any
# output option (--load-map and --cost-image too) is written in place and stays a device; a
# full device or a full disk fails the run (exit 1) with the errno's words, naming the target
# (not a temporary), and leaves no file. Skipped (exit 77) without root or unshare.
#
# Usage (CTest runs it so): bash tests/hostile/full_disk.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-render torusrt-sim
f=$(source_scene paper-image2) || exit 1
if [ "$(id -u)" -ne 0 ] || ! unshare -m true 2>/dev/null; then
    echo "$TEST_NAME: needs root and unshare -m: skipped"
    exit 77
fi
export TMP f BUILD
unshare -m --propagation private bash -c '
    cd "$TMP" || exit 90
    sim=("$BUILD/torusrt-sim" "$f" -q --t1 1 --ips 2 --size 24x24)
    render=("$BUILD/torusrt-render" "$f" -q --size 24x24)
    mkdir dev full d && mount -t tmpfs tmpfs dev && mount -t tmpfs -o size=64k tmpfs full || exit 90
    mknod -m 666 dev/null c 1 3 && mknod -m 666 dev/full c 1 7 || exit 90
    # Every output option on the null device: exit 0, still a device, nothing beside it.
    "${sim[@]}" -o d/a.png --load-map dev/null --write-map dev/null --stats dev/null --vcd dev/null; echo "sim_null $?"
    "${render[@]}" -o dev/null --cost-image dev/null --stats dev/null; echo "render_null $?"
    "$BUILD/torusrt-sim" "$f" -q --ips 2 --size 24x24 --frames 2 --orbit 10 -o d/f%d.png --frames-csv dev/null; echo "csv_null $?"
    test -c dev/null; echo "null_char $?"
    echo "dev_listing $(ls -A dev | tr "\n" " ")"
    rm -f d/*
    # Each output option on the full device: exit 1, the errno words, the device named.
    for opt in --load-map --write-map --stats --vcd; do
        "${sim[@]}" -o d/a.png $opt dev/full 2>"sim$opt.err"; echo "sim_full$opt $? $(ls -A d | tr "\n" " ")"
    done
    for opt in -o --cost-image --stats; do
        o=(-o d/a.png); [ $opt = -o ] && o=()
        "${render[@]}" "${o[@]}" $opt dev/full 2>"render$opt.err"; echo "render_full$opt $? $(ls -A d | tr "\n" " ")"
    done
    test -c dev/full; echo "full_char $?"
    # A full disk: a 64 KiB tmpfs with 4 KiB left, less than the pictures take.
    head -c $((60 * 1024)) /dev/zero >full/filler
    "$BUILD/torusrt-render" "$f" -q --size 48x48 -o full/a.png --cost-image full/c.png 2>render_disk.err
    echo "render_disk $? $(ls -A full | grep -v filler | tr "\n" " ")"
    "$BUILD/torusrt-sim" "$f" -q --t1 1 --ips 2 --size 48x48 -o full/a.png --load-map full/m.png 2>sim_disk.err
    echo "sim_disk $? $(ls -A full | grep -v filler | tr "\n" " ")"
' >"$TMP/ns.out" 2>"$TMP/ns.err"
ns() { awk -v k="$1" '$1 == k { $1 = ""; sub(/^ /, ""); print }' "$TMP/ns.out"; }
check "namespace set up: $(head -c 200 "$TMP/ns.err")" [ -n "$(ns sim_null)" ]
check "sim: every output on a null device: exit 0" [ "$(ns sim_null)" = 0 ]
check "render: every output on a null device: exit 0" [ "$(ns render_null)" = 0 ]
check "sim: --frames-csv on a null device: exit 0" [ "$(ns csv_null)" = 0 ]
check "the null device stays a character device" [ "$(ns null_char)" = 0 ]
check "nothing beside the devices: $(ns dev_listing)" [ "$(ns dev_listing)" = "full null" ]
for opt in --load-map --write-map --stats --vcd; do
    check "sim $opt on a full device: exit 1, nothing left: $(ns "sim_full$opt")" [ "$(ns "sim_full$opt")" = 1 ]
    check "sim $opt on a full device: names it with the errno's words: $(head -c 200 "$TMP/sim$opt.err")" \
        grep -q "dev/full: cannot write: No space left on device" "$TMP/sim$opt.err"
done
for opt in -o --cost-image --stats; do
    check "render $opt on a full device: exit 1, nothing left: $(ns "render_full$opt")" [ "$(ns "render_full$opt")" = 1 ]
    check "render $opt on a full device: names it with the errno's words: $(head -c 200 "$TMP/render$opt.err")" \
        grep -q "dev/full: cannot write: No space left on device" "$TMP/render$opt.err"
done
check "the full device stays a character device" [ "$(ns full_char)" = 0 ]
check "render on a full disk: exit 1, nothing left: $(ns render_disk)" [ "$(ns render_disk)" = 1 ]
check "render on a full disk: names the target: $(head -c 200 "$TMP/render_disk.err")" \
    grep -q "full/[ac].png: cannot write: No space left on device" "$TMP/render_disk.err"
check "sim on a full disk: exit 1, nothing left: $(ns sim_disk)" [ "$(ns sim_disk)" = 1 ]
check "sim on a full disk: names the target: $(head -c 200 "$TMP/sim_disk.err")" \
    grep -q "full/[am].png: cannot write: No space left on device" "$TMP/sim_disk.err"
finish
