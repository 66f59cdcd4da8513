#!/usr/bin/env bash
# numbers.sh - a number option given garbage on the command line: every numeric option of both
# commands refuses a word, a number glued to letters and a malformed number (exit 2, the option
# named, nothing written), and accepts a plain decimal. Octal- and hex-looking values (010,
# 0x10) and numbers in machine files are the option parser's to rule on (cli.sim_bad_options,
# cli.machine_file_syntax): not tested here.
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
finish
