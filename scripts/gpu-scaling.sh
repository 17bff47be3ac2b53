#!/usr/bin/env bash
# Cost per sample against sphere count on an NVIDIA GPU node, for two
# register caps, and the Cornell box with each sampler (docs/performance.md).
# Usage on the node: scripts/gpu-scaling.sh BUNDLE_DIR OUT_DIR [SECONDS]
set -uo pipefail
bundle=$(cd "$1" && pwd)
out=$2
seconds=${3:-3}
mkdir -p "$out"
root=$(cd "$(dirname "$0")/.." && pwd)
source "$(dirname "$0")/gpu-node-env.sh" "$bundle"
render=$bundle/orb-render
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv 2>/dev/null
for preset in 10 1k 100k 1m 10m; do
  python3 "$root/scripts/orb-gen.py" --preset $preset -o /tmp/orb-$preset.orb >/dev/null || echo "orb-gen $preset failed"
done
bench() {  # label, then orb-render arguments; prints one line
  local label=$1; shift
  local sps
  sps=$("$render" --benchmark "$@" --device NVIDIA --benchmark-seconds "$seconds" -q 2>&1 |
        sed -n 's/.*samples_per_second=\([0-9.e+]*\).*/\1/p' | tail -1)
  printf '%-44s %s\n' "$label" "${sps:-failed}"
}
echo "== registers (1m)"
ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose "$render" --benchmark /tmp/orb-1m.orb --device NVIDIA \
  --benchmark-seconds 0.5 2>&1 | grep -iE 'registers|spill|stack frame' | head -4
echo "== spheres at 1920x1080 (samples/s), register cap 80 (default) and 64, two rounds"
for round in 1 2; do
  for preset in 10 1k 100k 1m 10m; do
    bench "r$round $preset cap=80" /tmp/orb-$preset.orb --width 1920 --height 1080
    ORB_CL_OPTIONS=-cl-nv-maxrregcount=64 bench "r$round $preset cap=64" /tmp/orb-$preset.orb --width 1920 --height 1080
  done
done
echo "== cornell.scn (samples/s): sobol (default) and independent, three rounds"
for round in 1 2 3; do
  for size in "640 480" "1920 1080"; do
    set -- $size
    bench "r$round cornell $1x$2 sobol" "$root/scenes/cornell.scn" --width $1 --height $2
    bench "r$round cornell $1x$2 independent" "$root/scenes/cornell.scn" --width $1 --height $2 --sampler independent
  done
done
