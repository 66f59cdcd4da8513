#!/usr/bin/env bash
# The main job: the simulator on the paper's first scene (16 IPs as a 4x2x2 torus, cyclic mapping).
# Writes results/paper-image1.png, results/paper-image1.json and results/paper-image1-summary.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
mkdir -p results
build/torusrt-sim scenes/paper-image1.nff --ips 4x2x2 --map cyclic \
  -o results/paper-image1.png --stats results/paper-image1.json | tee results/paper-image1-summary.txt
