#!/usr/bin/env bash
# Installs what is needed, builds from scratch if there is no build yet, and runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cd build
ctest --output-on-failure -j"$(nproc)" "$@"
