#!/usr/bin/env bash
# Measures orb-render on a GPU node from a bundle made by scripts/gpu-bundle.sh
# (the figures in docs/performance.md come from this script's output).
# Usage on the node: scripts/gpu-benchmark.sh BUNDLE_DIR OUT_DIR
# Registers NVIDIA's OpenCL driver with the ICD loader for this run only when
# the node has it but no loader entry for it (docs/performance.md, "How to reproduce").
set -uo pipefail
bundle=$(cd "$1" && pwd)
out=$2
mkdir -p "$out"
source "$(dirname "$0")/gpu-node-env.sh" "$bundle"
render=$bundle/orb-render
scenes=$(dirname "$0")/../scenes
run() { echo "\$ orb-render $*"; "$render" "$@"; echo "(exit $?)"; }

nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv 2>/dev/null
run --list-devices
# Throughput: warm-up passes, then timed passes; no image.
run --benchmark "$scenes/cornell.scn" --device NVIDIA --benchmark-seconds 10
run --benchmark "$scenes/cornell.scn" --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 10
for s in simple caustic caustic3 cornell_large; do
  run --benchmark "$scenes/$s.scn" --device NVIDIA --benchmark-seconds 5
done
run --benchmark "$scenes/cornell.scn" --device Portable --benchmark-seconds 10
# The paper's Figure 8: the same samples on the CPU device and on the GPU device.
run "$scenes/cornell.scn" --device NVIDIA --spp 1024 --seed 7 -o "$out/cornell-gpu.exr" --passes beauty --stats-json "$out/gpu.json"
run "$scenes/cornell.scn" --device Portable --spp 1024 --seed 7 -o "$out/cornell-cpu.exr" --passes beauty --stats-json "$out/cpu.json"
cat "$out/gpu.json" "$out/cpu.json"
# The GPU end to end: start-up, denoising, adaptive sampling, batches.
"$(dirname "$0")/gpu-end-to-end.sh" "$bundle" "$out/end-to-end"
