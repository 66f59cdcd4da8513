#!/usr/bin/env bash
# inputs.sh - every input option of both programs given a file that is not a regular text file:
# a FIFO with no writer, /dev/zero, a folder, a device node (a block device where root may make
# one), a file with a NUL byte. Each is refused at once (exit 1 or 2, never a hang: 124 is a
# hang), with a message naming the option (for the options that name files) and the file and
# saying what it is, and no output file. A UTF-8 byte-order mark is skipped in every input.
#
# Usage (CTest runs it so): bash tests/hostile/inputs.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-render torusrt-sim
time_limit 20
scene=$(source_scene one-pixel) || exit 1
sim="$BUILD/torusrt-sim"
render="$BUILD/torusrt-render"
mkfifo "$TMP/fifo"
mkdir "$TMP/folder"
if [ "$(id -u)" -eq 0 ] && mknod "$TMP/block" b 7 0 2>/dev/null; then block="$TMP/block"; else block=""; fi
printf 'link = 5\0 0\n' >"$TMP/nul.toml"
printf 'torusrt-map 1 1 1 1 1\n0\0\n' >"$TMP/nul.map"
printf '0 0 5 0 0 0 0 1 0 45\n\0\n' >"$TMP/nul.path"
printf 'link = 5\n\0\n' >"$TMP/nul.timing"
printf 'v\nfrom 0 0 5\nat 0 0 0\n\0' >"$TMP/nul.nff"
printf 'frames 2\n\0\n' >"$TMP/nul.motion"

# refused NAME WANT_STATUS PATTERN COMMAND...: the run fails with that status, stderr holds
# PATTERN, and the output folder stays empty.
refused() {
    local name=$1 want=$2 pattern=$3
    shift 3
    rm -rf "$TMP/out" && mkdir "$TMP/out"
    "${run_limited[@]}" "$@" >/dev/null 2>"$TMP/$name.err" </dev/null
    local rc=$?
    check "$name: exit $rc, expected $want (124: hung): $(head -c 300 "$TMP/$name.err")" [ "$rc" -eq "$want" ]
    check "$name: stderr lacks '$pattern': $(head -c 300 "$TMP/$name.err")" grep -qF -- "$pattern" "$TMP/$name.err"
    check "$name: left files behind: $(ls -A "$TMP/out")" [ -z "$(ls -A "$TMP/out")" ]
}

# Each hostile file with what the message must say about it.
kinds=("fifo:$TMP/fifo: is a FIFO, not a regular file"
       "zero:/dev/zero: is a character device, not a regular file"
       "folder:$TMP/folder: is a folder, not a regular file")
[ -n "$block" ] && kinds+=("block:$block: is a block device, not a regular file")
path_of() { case $1 in fifo) echo "$TMP/fifo" ;; zero) echo /dev/zero ;; folder) echo "$TMP/folder" ;; block) echo "$block" ;; esac; }

for entry in "${kinds[@]}"; do
    kind=${entry%%:*} says=${entry#*:} p=$(path_of "${entry%%:*}")
    for exe in render sim; do
        eval "prog=\$$exe"
        refused "$exe-scene-$kind" 1 "$says" "$prog" "$p" -o "$TMP/out/a.png" -q
        refused "$exe-timing-$kind" 1 "$says" "$prog" "$scene" --timing "$p" -o "$TMP/out/a.png" -q
        refused "$exe-camera-path-$kind" 2 "--camera-path: $says" "$prog" "$scene" --camera-path "$p" \
            -o "$TMP/out/f%d.png" -q
        refused "$exe-motion-$kind" 2 "--motion: $says" "$prog" "$scene" --motion "$p" -o "$TMP/out/f%d.png" -q
    done
    refused "sim-config-$kind" 2 "--config: $says" "$sim" "$scene" --config "$p" -o "$TMP/out/a.png" -q
    refused "sim-dump-config-$kind" 2 "--config: $says" "$sim" --dump-config --config "$p"
    refused "sim-map-file-$kind" 2 "--map-file: $says" "$sim" "$scene" --map-file "$p" -o "$TMP/out/a.png" -q
done

# A NUL byte: refused naming the file and its line.
for exe in render sim; do
    eval "prog=\$$exe"
    refused "$exe-scene-nul" 1 "$TMP/nul.nff:4: binary data" "$prog" "$TMP/nul.nff" -o "$TMP/out/a.png" -q
    refused "$exe-timing-nul" 1 "$TMP/nul.timing:2: binary data" "$prog" "$scene" --timing "$TMP/nul.timing" \
        -o "$TMP/out/a.png" -q
    refused "$exe-camera-path-nul" 2 "$TMP/nul.path:2: binary data" "$prog" "$scene" --camera-path "$TMP/nul.path" \
        -o "$TMP/out/f%d.png" -q
    refused "$exe-motion-nul" 2 "--motion: $TMP/nul.motion:2: binary data" "$prog" "$scene" --motion "$TMP/nul.motion" \
        -o "$TMP/out/f%d.png" -q
done
refused "sim-config-nul" 2 "--config: $TMP/nul.toml:1: binary data" "$sim" --dump-config --config "$TMP/nul.toml"
refused "sim-map-file-nul" 2 "$TMP/nul.map:2: binary data" "$sim" "$scene" --map-file "$TMP/nul.map" -o "$TMP/out/a.png" -q

# A byte-order mark is skipped: each input with one reads as the same input without it.
bom=$'\xef\xbb\xbf'
"$sim" --dump-config --ips 2 >"$TMP/m.toml" || fail "--dump-config"
{ printf '%s' "$bom"; cat "$TMP/m.toml"; } >"$TMP/bom.toml"
check "sim: a --config file with a BOM reads as without ($("$sim" --dump-config --config "$TMP/bom.toml" 2>&1 | head -c 200))" \
    cmp -s <("$sim" --dump-config --config "$TMP/bom.toml" 2>&1) <("$sim" --dump-config --config "$TMP/m.toml" 2>&1)
printf '%storusrt-map 1 1 1 1 1\n0\n' "$bom" >"$TMP/bom.map"
check "sim: a --map-file with a BOM is read" "$sim" "$scene" --map-file "$TMP/bom.map" --cells 1 -o "$TMP/bom.png" -q
printf '%s0 0 5 0 0 0 0 1 0 45\n' "$bom" >"$TMP/bom.path"
check "render: a --camera-path with a BOM is read" "$render" "$scene" --camera-path "$TMP/bom.path" -o "$TMP/bom%d.png" -q
printf '%sframes 2\n' "$bom" >"$TMP/bom.motion"
check "render: a --motion file with a BOM is read" "$render" "$scene" --motion "$TMP/bom.motion" -o "$TMP/bomm%d.png" -q
{ printf '%s' "$bom"; cat "$SRC/timing/literal.timing"; } >"$TMP/bom.timing"
check "render: a --timing file with a BOM is read" "$render" "$scene" --timing "$TMP/bom.timing" -o "$TMP/bomt.png" -q
finish
