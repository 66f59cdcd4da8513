#!/usr/bin/env bash
# The model as a library: installs the build into a temporary prefix, builds
# testbench/examples (find_package(torusrt)) and the same example through pkg-config, runs both
# on a small scene, and checks that they report torusrt-sim's image time for the same 2x2 torus.
# Usage: library_example.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=DISABLE
scene=$src/scenes/paper-image1.nff
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log"
for f in include/torusrt/model_run.h include/torusrt/rt_scene.h include/torusrt/user_error.h \
         lib/cmake/torusrt/torusrtConfig.cmake lib/pkgconfig/torusrt.pc lib/libtorusrt_model.a; do
    [[ -f $tmp/prefix/$f ]] || fail "not installed: $f"
done
# The library needs no command-line parser.
! grep -q CLI11 "$tmp"/prefix/lib/cmake/torusrt/torusrtTargets*.cmake || fail "the installed model depends on CLI11"
! grep -rlq 'CLI/CLI.hpp' "$tmp/prefix/include/torusrt" || fail "an installed header includes CLI11: $(grep -rl 'CLI/CLI.hpp' "$tmp/prefix/include/torusrt")"

cmake -S "$src/testbench/examples" -B "$tmp/ex" -DCMAKE_PREFIX_PATH="$tmp/prefix" \
      -DCMAKE_BUILD_TYPE=Release > "$tmp/ex.log" || { cat "$tmp/ex.log"; fail "configuring the example"; }
cmake --build "$tmp/ex" > "$tmp/exbuild.log" 2>&1 || { cat "$tmp/exbuild.log"; fail "building the example"; }
! grep -q 'warning:' "$tmp/exbuild.log" || { cat "$tmp/exbuild.log"; fail "warnings building the example"; }

# The same source through pkg-config.
PKG_CONFIG_PATH=$tmp/prefix/lib/pkgconfig
export PKG_CONFIG_PATH
# shellcheck disable=SC2046  # the flags are words
c++ -std=c++17 -O1 -o "$tmp/two_by_two_pc" "$src/testbench/examples/two_by_two.cpp" \
    $(pkg-config --cflags --libs torusrt) || fail "building the example with pkg-config"

"$build/torusrt-sim" "$scene" --ips 2x2 --size 16x16 -q -o "$tmp/sim.png" --stats "$tmp/sim.json"
want=$(jq -r '.sim_time_s' "$tmp/sim.json")
# The scene must tell machine shapes apart, or matching times would prove nothing.
"$build/torusrt-sim" "$scene" --ips 2x1 --size 16x16 -q -o "$tmp/other.png" --stats "$tmp/other.json"
jq -e --argjson t "$want" '.sim_time_s != $t' "$tmp/other.json" > /dev/null || fail "2x1 and 2x2 give the same time"
for exe in "$tmp/ex/two_by_two" "$tmp/two_by_two_pc"; do
    "$exe" "$scene" 16 16 > "$tmp/out.txt" || fail "$exe exited with $?"
    grep -qx 'packets conserved' "$tmp/out.txt" || fail "$exe: no conservation line"
    got=$(awk '$1 == "image_time_s" { print $2 }' "$tmp/out.txt")
    [[ -n $got ]] || fail "$exe printed no image time"
    jq -e --argjson t "$got" '.sim_time_s == $t and $t > 0' "$tmp/sim.json" > /dev/null \
        || fail "$exe: image time $got, torusrt-sim $want"
done
# A bad scene path is a clear error with exit 1, not a crash.
if "$tmp/ex/two_by_two" "$tmp/missing.nff" 2> "$tmp/err.txt"; then fail "a missing scene was accepted"; fi
grep -q 'missing.nff' "$tmp/err.txt" || fail "the error does not name the file"
echo "ok: image time $want s from the installed library, as torusrt-sim"
