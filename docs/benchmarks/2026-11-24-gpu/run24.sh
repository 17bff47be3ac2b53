#!/usr/bin/env bash
# H100, 2026-11-24 (third session): the sampler's divergence. Nsight Compute
# (run22) shows the Cornell box's Sobol hashing running at 7-11 of 32 lanes:
# lanes at different depths take Sobol (blocks 0-2) or Philox (later), and
# lanes at delta vertices skip the light and direction pairs. Variants:
#   hoist     (.gpu/kvar = kernels/ of b5aa821 with hoist-experiment.patch,
#             -DEXP_HOIST, a prototype of what extend_path now
#             does on GPUs): every lane draws all of a block's
#             numbers before the branches; the image is bit-identical
#   sobol8    -DORB_SOBOL_BLOCKS=8: Sobol for every block up to depth 7,
#             so no lane takes Philox (other numbers: not bit-identical)
#   independent (--sampler independent), for reference.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 10 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
bench() {  # label, options, extra args, scene args...
  local label=$1 options=$2; shift 2
  echo -n "$label: "
  ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$options" timeout 120 "$B/orb-render" --benchmark "$@" --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
}
for round in 1 2; do
  for scene in "scenes/cornell.scn" "$W/bench-10.orb --width 1920 --height 1080" "$W/bench-1m.orb --width 1920 --height 1080"; do
    echo "== round $round $scene"
    bench main "" $scene
    bench hoist "-DEXP_HOIST" $scene
    bench sobol8 "-DORB_SOBOL_BLOCKS=8" $scene
    bench hoist+sobol8 "-DEXP_HOIST -DORB_SOBOL_BLOCKS=8" $scene
    bench independent "" $scene --sampler independent
  done
done
