#!/usr/bin/env bash
# H100, 2026-11-24: would a wavefront renderer pay? The megakernel's samples/s
# at 10, 100 k and 1 M spheres next to ray casting alone (orb-trace-benchmark)
# on the same scenes, 1920x1080, and the registers NVIDIA gives each kernel.
# Run from the repository root on the GPU node with the bundle in .gpu/b.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv
for p in 10 100k 1m; do python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
for round in 1 2; do
  for p in 10 100k 1m; do
    echo "== round $round megakernel $p"
    "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 3 -q 2>&1 | tail -2
  done
  for p in 100k 1m; do
    echo "== round $round trace_rays $p"
    "$B/orb-trace-benchmark" $W/bench-$p.orb --device NVIDIA --seconds 2 2>&1
  done
done
echo "== registers"
ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose "$B/orb-trace-benchmark" $W/bench-1m.orb --device NVIDIA --seconds 0.2 2>&1 |
  grep -iE "trace_rays|render_pass|registers|spill|stack" | head -20
for cap in 32 48 64; do
  echo "== trace_rays 1m with -cl-nv-maxrregcount=$cap"
  ORB_CL_OPTIONS=-cl-nv-maxrregcount=$cap "$B/orb-trace-benchmark" $W/bench-1m.orb --device NVIDIA --seconds 2 2>&1
done
