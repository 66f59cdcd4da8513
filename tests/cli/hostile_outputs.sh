#!/usr/bin/env bash
# Outputs that are devices stay devices; a run's outputs commit together or not at all; every
# write error fails the run; -o may not be the scene. The device and full-disk cases run in a
# private mount namespace (unshare -m) on their own tmpfs with their own device nodes, never on
# the real /dev (a run that replaces the node must not break the machine); without unshare or
# root they are skipped (exit 77).
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
f="$SRC/scenes/paper-image2.nff"
sim=("$BUILD/torusrt-sim" --ips 2x2 --size 24x24 --t1 1 -q)
render=("$BUILD/torusrt-render" --size 24x24 -q)

# -o naming the scene (also through another path) or two outputs naming one file: exit 2.
cp "$f" "$TMP/scene.nff"
ln "$TMP/scene.nff" "$TMP/hardlink.nff"
before=$(md5sum < "$TMP/scene.nff")
for exe in sim render; do
    eval "cmd=(\"\${$exe[@]}\")"
    "${cmd[@]}" "$TMP/scene.nff" -o "$TMP/../$(basename "$TMP")/scene.nff" 2>"$TMP/err"
    check "$exe: -o the scene itself exits 2" test $? -eq 2
    "${cmd[@]}" "$TMP/scene.nff" -o "$TMP/hardlink.nff" 2>/dev/null
    check "$exe: -o a hard link of the scene exits 2" test $? -eq 2
    "${cmd[@]}" "$TMP/scene.nff" -o "$TMP/x.png" --stats "./$(realpath --relative-to=. "$TMP/x.png")" 2>/dev/null
    check "$exe: -o and --stats naming one file exits 2" test $? -eq 2
done
mkdir "$TMP/x.gtkw"
"${sim[@]}" "$f" -o "$TMP/x.png" --vcd "$TMP/x.vcd" 2>/dev/null
check "sim: a folder where the save file goes exits 2" test $? -eq 2
check "sim: ... and leaves no VCD" test ! -e "$TMP/x.vcd"
check "the scene is unchanged" test "$(md5sum < "$TMP/scene.nff")" = "$before"
check "no x.png left" test ! -e "$TMP/x.png"

# In a private mount namespace: a tmpfs holding a character device, and a 64 KiB tmpfs.
if ! unshare -m true 2>/dev/null || [ "$(id -u)" -ne 0 ]; then
    echo "$TEST_NAME: unshare -m or root not available: namespace cases skipped"
    finish || exit 1
    exit 77
fi
export TMP f
export SIM="${sim[*]}" RENDER="${render[*]}"
unshare -m --propagation private bash -c '
    mkdir -p "$TMP/dev" "$TMP/full"
    mount -t tmpfs tmpfs "$TMP/dev" && mknod -m 666 "$TMP/dev/null" c 1 3 || exit 90
    mount -t tmpfs -o size=64k tmpfs "$TMP/full" || exit 90
    mkdir "$TMP/devfull" && mount -t tmpfs tmpfs "$TMP/devfull" && mknod -m 666 "$TMP/devfull/full" c 1 7 || exit 90
    mkdir "$TMP/d"
    $SIM "$f" -o "$TMP/d/a.png" --stats "$TMP/d/a.json" --vcd "$TMP/devfull/full" 2>"$TMP/devfull.err"; echo "vcd_full $?"
    echo "vcd_full_listing $(ls -A "$TMP/d" | tr "\n" " ")"
    mkdir "$TMP/d2"
    $SIM "$f" -o "$TMP/devfull/full" --stats "$TMP/d2/a.json" --vcd "$TMP/d2/a.vcd" 2>/dev/null; echo "png_full $?"
    echo "png_full_listing $(ls -A "$TMP/d2" | tr "\n" " ")"
    $RENDER "$f" -o "$TMP/devfull/full" 2>/dev/null; echo "render_full $?"
    test -c "$TMP/devfull/full"; echo "full_still_char $?"
    $SIM "$f" -o "$TMP/dev/null" --stats "$TMP/dev/null" --vcd "$TMP/dev/null"; echo "sim_dev $?"
    test -c "$TMP/dev/null"; echo "sim_still_char $?"
    $RENDER "$f" -o "$TMP/dev/null" --stats "$TMP/dev/null"; echo "render_dev $?"
    test -c "$TMP/dev/null"; echo "render_still_char $?"
    echo "dev_listing $(ls -A "$TMP/dev" | tr "\n" " ")"
    $SIM "$f" -o "$TMP/full/a.png" --stats "$TMP/full/a.json" --vcd "$TMP/full/a.vcd" 2>"$TMP/full.err"; echo "full_rc $?"
    echo "full_listing $(ls -A "$TMP/full" | tr "\n" " ")"
' > "$TMP/ns.out" 2>"$TMP/ns.err"
ns() { awk -v k="$1" '$1 == k { $1 = ""; sub(/^ /, ""); print }' "$TMP/ns.out"; }
check "namespace set up ($(head -c 200 "$TMP/ns.err"))" test -n "$(ns sim_dev)"
check "--vcd on a full device exits 1" test "$(ns vcd_full)" = 1
check "--vcd on a full device: message names it" grep -q 'devfull/full' "$TMP/devfull.err"
check "--vcd on a full device: no PNG or JSON left ($(ns vcd_full_listing))" test -z "$(ns vcd_full_listing)"
check "-o on a full device exits 1" test "$(ns png_full)" = 1
check "-o on a full device: no VCD, save file or JSON left ($(ns png_full_listing))" test -z "$(ns png_full_listing)"
check "render -o a full device exits 1" test "$(ns render_full)" = 1
check "the full device stays a character device" test "$(ns full_still_char)" = 0
check "sim to a device node exits 0" test "$(ns sim_dev)" = 0
check "sim leaves the device a character device" test "$(ns sim_still_char)" = 0
check "render to a device node exits 0" test "$(ns render_dev)" = 0
check "render leaves the device a character device" test "$(ns render_still_char)" = 0
check "no files beside the device ($(ns dev_listing))" test "$(ns dev_listing)" = null
check "full disk: exit 1" test "$(ns full_rc)" = 1
check "full disk: message says no space" grep -q 'No space left' "$TMP/full.err"
check "full disk: no output files ($(ns full_listing))" test -z "$(ns full_listing)"
finish
