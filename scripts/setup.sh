#!/usr/bin/env bash
# Installs the Debian packages torusrt needs (if missing) and builds it in build/ (Release).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ make pkg-config libsystemc-dev libpng-dev nlohmann-json3-dev libcli11-dev
          libgtest-dev gtkwave gnuplot-nox parallel jq time)
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

# Build output goes to build/build.log and is shown only when the build fails.
mkdir -p build
if ! { cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j"$(nproc)"; } > build/build.log 2>&1; then
  cat build/build.log
  echo "setup: the build failed (log: build/build.log)" >&2
  exit 1
fi
echo "setup: built torusrt in build/ (log: build/build.log)"
