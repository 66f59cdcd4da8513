#!/usr/bin/env bash
# numbers.sh - a number option given garbage on the command line: every numeric option of both
# commands refuses a word, a number glued to letters and a malformed number (exit 2, the option
# named, nothing written), and accepts a plain decimal. Octal- and hex-looking values (010,
# 0x10) and numbers in machine files are the option parser's to rule on (cli.sim_bad_options,
# cli.machine_file_syntax). The file formats read their numbers with the same decimal syntax
# (include/rt_number.h): a motion file, a camera path, a map file and a timing file each refuse
# a leading zero, a plus sign, a bare point, hex and an underflow to 0 (1e-400), naming the file
# and line, and write nothing.
#
# Usage (CTest runs it so): bash tests/hostile/numbers.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-render torusrt-sim
time_limit 30
scene=$(source_scene one-pixel) || exit 1
sim="$BUILD/torusrt-sim"
size=(--size 2x2)

# Each option with a decimal value it accepts.
common=("--cells 4" "--size 2x2" "--max-depth 3" "--min-weight 0.01" "--memory-budget 64M")
sim_only=("--ips 2" "--queue 8" "--cluster 2" "--link-us 20" "--packet-bytes 28" "--link-bytes-per-us 2"
          "--time-limit 1s" "--t1 1")
garbage=("seven" "12q" "1.2.3")
for entry in "${common[@]}" "${sim_only[@]}"; do
    option=${entry%% *} good=${entry#* }
    for bad in "${garbage[@]}"; do
        [ "$option" = --size ] && size=()  # bad_option passes ${size[@]} itself
        bad_option "$option" "sim $option=$bad" "$option=$bad"
        size=(--size 2x2)
    done
    sized=("${size[@]}")
    [ "$option" = --size ] && sized=()
    check "sim $option $good is accepted" "$sim" "$scene" "${sized[@]}" -q "$option" "$good" -o "$TMP/good.png"
done
for entry in "${common[@]}"; do
    option=${entry%% *} good=${entry#* }
    for bad in "${garbage[@]}"; do
        rm -rf "$TMP/bad" && mkdir "$TMP/bad"
        "${run_limited[@]}" "$BUILD/torusrt-render" "$scene" "${size[@]}" -q "$option=$bad" -o "$TMP/bad/a.png" \
            >/dev/null 2>"$TMP/r.err" </dev/null
        rc=$?
        check "render $option=$bad: exit 2 (got $rc)" [ "$rc" -eq 2 ]
        check "render $option=$bad: names $option: $(head -c 200 "$TMP/r.err")" grep -q -- "$option" "$TMP/r.err"
        check "render $option=$bad: no output" [ -z "$(ls -A "$TMP/bad")" ]
    done
    sized=("${size[@]}")
    [ "$option" = --size ] && sized=()
    check "render $option $good is accepted" "$BUILD/torusrt-render" "$scene" "${sized[@]}" -q "$option" "$good" \
        -o "$TMP/good.png"
done

# file_refuses NAME FILE LINE COMMAND...: COMMAND (writing into $TMP/bad) exits non-zero, names
# FILE:LINE and writes nothing.
file_refuses() {
    local name=$1 file=$2 line=$3
    shift 3
    rm -rf "$TMP/bad" && mkdir "$TMP/bad"
    "${run_limited[@]}" "$@" >/dev/null 2>"$TMP/f.err" </dev/null
    local rc=$?
    check "$name: refused (exit $rc)" [ "$rc" -ne 0 ]
    check "$name: names $(basename "$file"):$line ($(head -c 200 "$TMP/f.err"))" grep -qF -- "$file:$line:" "$TMP/f.err"
    check "$name: no output" [ -z "$(ls -A "$TMP/bad")" ]
}
render="$BUILD/torusrt-render"
reals=("010" "+5" ".5" "5." "0x10" "1e-400" "-1e-330")
for bad in "${reals[@]}"; do
    printf 'frames 2\nobjects 0\nkey 0 move 0 0 0\nkey 1 move %s 0 0\n' "$bad" >"$TMP/m.motion"
    file_refuses "motion move $bad" "$TMP/m.motion" 4 "$render" "$scene" "${size[@]}" -q --motion "$TMP/m.motion" \
        -o "$TMP/bad/f_%d.png"
    printf '# a pose\n0 0 -5  0 0 0  0 1 0  %s\n' "$bad" >"$TMP/c.path"
    file_refuses "camera path angle $bad" "$TMP/c.path" 2 "$render" "$scene" "${size[@]}" -q \
        --camera-path "$TMP/c.path" -o "$TMP/bad/f_%d.png"
    printf 'link %s\n' "$bad" >"$TMP/t.timing"
    file_refuses "timing file link $bad" "$TMP/t.timing" 1 "$sim" "$scene" "${size[@]}" -q --timing "$TMP/t.timing" \
        -o "$TMP/bad/a.png"
done
for bad in "01" "+1" "0x1" "1.0"; do
    printf 'frames %s\n' "$bad" >"$TMP/m.motion"
    file_refuses "motion frames $bad" "$TMP/m.motion" 1 "$render" "$scene" "${size[@]}" -q --motion "$TMP/m.motion" \
        -o "$TMP/bad/f_%d.png"
    { echo "torusrt-map 1 2 2 2 2"; for c in 0 1 2 3 4 5 6; do echo 0; done; echo "$bad"; } >"$TMP/m.map"
    file_refuses "map file node $bad" "$TMP/m.map" 9 "$sim" "$scene" "${size[@]}" -q --cells 2 --ips 2 \
        --map-file "$TMP/m.map" -o "$TMP/bad/a.png"
done
# The plain forms of the same numbers are accepted.
printf 'frames 2\nobjects 0\nkey 0 move 0 0 0\nkey 1 move 0.5 5 -1e-3\n' >"$TMP/m.motion"
check "motion file with plain numbers is accepted" "$render" "$scene" "${size[@]}" -q --motion "$TMP/m.motion" \
    -o "$TMP/good_%d.png"
# A tiny 'up' in a camera path keeps its direction, as a motion file's axis does: the
# frames equal those of 'up 0 1 0'; the zero vector is refused as zero.
image=$(source_scene paper-image1) || exit 1
for up in "0 1e-300 0" "0 1e-200 0"; do
    rm -f "$TMP"/up_*.png "$TMP"/one_*.png
    printf '0 0 -5  0 0 0  %s  40\n0 1 -5  0 0 0  %s  40\n' "$up" "$up" >"$TMP/c.path"
    printf '0 0 -5  0 0 0  0 1 0  40\n0 1 -5  0 0 0  0 1 0  40\n' >"$TMP/c1.path"
    "$render" "$image" --size 8x8 -q --camera-path "$TMP/c.path" -o "$TMP/up_%d.png" 2>"$TMP/f.err"
    rc=$?
    check "camera path up $up: accepted (exit $rc: $(head -c 200 "$TMP/f.err"))" [ "$rc" -eq 0 ]
    "$render" "$image" --size 8x8 -q --camera-path "$TMP/c1.path" -o "$TMP/one_%d.png"
    check "camera path up $up: the frames of up 0 1 0" cmp -s "$TMP/up_1.png" "$TMP/one_1.png"
done
printf '0 0 -5  0 0 0  0 0 0  40\n' >"$TMP/c.path"
file_refuses "camera path up 0 0 0" "$TMP/c.path" 1 "$render" "$scene" "${size[@]}" -q --camera-path "$TMP/c.path" \
    -o "$TMP/bad/f_%d.png"
check "camera path up 0 0 0: says zero" grep -q "'up' is zero" "$TMP/f.err"
{ echo "torusrt-map 1 2 2 2 2"; for c in 0 1 2 3 4 5 6 7; do echo $((c % 2)); done; } >"$TMP/m.map"
check "map file with plain numbers is accepted" "$sim" "$scene" "${size[@]}" -q --cells 2 --ips 2 \
    --map-file "$TMP/m.map" -o "$TMP/good.png"
finish
