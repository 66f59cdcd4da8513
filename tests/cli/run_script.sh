#!/usr/bin/env bash
# scripts/run.sh and scripts/setup.sh tell the user what they do: setup.sh announces the build
# and its log, run.sh prints the path of every file it wrote. Run on a copy of the scripts with
# stand-in cmake and torusrt-sim (the real main job takes minutes).
source "$(dirname "$0")/common.bash" "$@"
tree="$TMP/tree"
mkdir -p "$tree/scripts" "$tree/bin" "$tree/build"
cp "$SRC/scripts/run.sh" "$SRC/scripts/setup.sh" "$tree/scripts/"
# cmake: a configure and a build that print progress like CMake's and last past one progress line.
cat > "$tree/bin/cmake" <<'STUB'
#!/usr/bin/env bash
case "$*" in *--build*) echo "[ 50%] Building"; sleep 17; echo "[100%] Built" ;; *) echo "-- Configuring done" ;; esac
STUB
# torusrt-sim: writes its -o and --stats files and a summary.
cat > "$tree/build/torusrt-sim" <<'STUB'
#!/usr/bin/env bash
while [ $# -gt 0 ]; do
  case "$1" in -o|--stats) echo data > "$2"; shift ;; esac
  shift
done
echo "torusrt-sim: summary"
STUB
chmod +x "$tree/bin/cmake" "$tree/build/torusrt-sim"
PATH="$tree/bin:$PATH" bash "$tree/scripts/run.sh" > "$TMP/out" 2>&1
check "run.sh exits 0 ($(tail -n 3 "$TMP/out"))" test $? -eq 0
check "setup announces the build and its log" grep -q "^setup: building torusrt in build/ .*log: build/build.log" "$TMP/out"
check "setup shows the build's progress while it runs" grep -q '^setup: building\.\.\. \[ 50%\]' "$TMP/out"
for f in paper-image1.png paper-image1.json paper-image1-summary.txt; do
  check "run.sh prints the path of $f" grep -qx "run: wrote $tree/results/$f" "$TMP/out"
  check "$f exists" test -s "$tree/results/$f"
done
finish
