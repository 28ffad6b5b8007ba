#!/usr/bin/env bash
# The main job end to end: render the paper's simulated scene (Section IV-B,
# aligned rig), run the fixed-point firmware pipeline on it at 40x30, print the
# error summary and write a plot of estimate and truth.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/setup-debian.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target lumavel-sim
out=out/demo
rm -rf "$out" && mkdir -p "$out"
build/host_sim/sim/lumavel-sim render host_sim/scenarios/paper_sim_aligned.yaml "$out/rec" --resolution 160x120
build/host_sim/sim/lumavel-sim run "$out/rec" --width 40 --height 30 -o "$out/estimates.csv" --plot "$out/estimates.svg"
echo "estimates: $out/estimates.csv   plot: $out/estimates.svg"
