#!/usr/bin/env bash
# Installs the Debian packages torusrt needs (if missing) and builds it in build/ (Release).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ make pkg-config libsystemc-dev libpng-dev nlohmann-json3-dev libcli11-dev
          libtomlplusplus-dev
          libgtest-dev gtkwave gnuplot-nox parallel jq clang time
          libscotch-dev)
packages+=(python3)  # report generation (experiments/report) and its tests
packages+=(clang-format)  # the format audit (audit.format, scripts/check_format.py)
packages+=(slurm-wlm slurm-client munge iproute2 util-linux)  # the Slurm backend's test (tests/slurm)
packages+=(xvfb xauth)  # the GTKWave test opens a trace in GTKWave on a virtual X display
packages+=(linux-perf)  # bench/profile.sh: where a run's CPU time goes (perf record)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q "${missing[@]}"
fi

# Build output goes to build/build.log and is shown only when the build fails; while it runs,
# its progress (CMake's percentage) is printed every 15 seconds.
mkdir -p build
echo "setup: building torusrt in build/ (minutes the first time; log: build/build.log)"
{ cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j"$(nproc)"; } > build/build.log 2>&1 &
build_pid=$!
seconds=0
while kill -0 "$build_pid" 2>/dev/null; do
  sleep 1
  seconds=$((seconds + 1))
  if [ $((seconds % 15)) -eq 0 ] && kill -0 "$build_pid" 2>/dev/null; then
    echo "setup: building... $(grep -o '^\[ *[0-9]*%\]' build/build.log | tail -n 1) (${seconds} s)"
  fi
done
if ! wait "$build_pid"; then
  cat build/build.log
  echo "setup: the build failed (log: build/build.log)" >&2
  exit 1
fi
echo "setup: built torusrt in build/ (log: build/build.log)"
