#!/usr/bin/env bash
# The main job: the simulator on the paper's first scene (16 IPs as a 4x2x2 torus, cyclic mapping).
# Builds first (scripts/setup.sh), then writes results/paper-image1.png, results/paper-image1.json
# and results/paper-image1-summary.txt, and prints their paths.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
mkdir -p results
echo "run: torusrt-sim on scenes/paper-image1.nff, 4x2x2 torus (the simulation takes a while)"
build/torusrt-sim scenes/paper-image1.nff --ips 4x2x2 --map cyclic \
  -o results/paper-image1.png --stats results/paper-image1.json | tee results/paper-image1-summary.txt
for f in results/paper-image1.png results/paper-image1.json results/paper-image1-summary.txt; do
  echo "run: wrote $PWD/$f"
done
