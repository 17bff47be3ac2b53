#!/usr/bin/env bash
# H100, 2026-11-24 (third session): speculative while-while traversal (Aila
# and Laine 2009) in render_pass. Nsight Compute (run22) showed the leaves at
# 2-3 of 32 lanes at 1 M spheres. .gpu/kvar = kernels/ of this commit with
# speculative-traversal.patch: -DEXP_SPECULATIVE=1 postpones a lane's leaf
# until every converged lane of the warp holds one (vote.sync.any through
# inline PTX, -DEXP_VOTE=1), or, with -DEXP_VOTE=0, until the lane itself
# holds one (plain while-while). Images bit-identical on PoCL.
# main beside them, 100 k and 1 M spheres at 1920x1080, two rounds; then
# Nsight Compute's lanes for the speculative build at 1 M.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
NCU=/usr/local/cuda/bin/ncu
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 1k 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
bench() {  # label, options, scene args...
  local label=$1 options=$2; shift 2
  echo -n "$label: "
  ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$options" timeout 120 "$B/orb-render" --benchmark "$@" --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
}
for round in 1 2; do
  for p in 1k 100k 1m; do
    echo "== round $round $p"
    bench main "" $W/bench-$p.orb --width 1920 --height 1080
    bench speculative "-DEXP_SPECULATIVE=1 -DEXP_VOTE=1" $W/bench-$p.orb --width 1920 --height 1080
    bench while-while "-DEXP_SPECULATIVE=1 -DEXP_VOTE=0" $W/bench-$p.orb --width 1920 --height 1080
  done
done
echo "== registers"
for v in "" "-DEXP_SPECULATIVE=1 -DEXP_VOTE=1"; do
  ORB_SHOW_BUILD_LOG=1 ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v -cl-nv-verbose" timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 64 --height 64 --spp 1 -o /tmp/v.exr -q 2>&1 | grep -E "stack frame|Used" | head -2
done
for v in "" "-DEXP_SPECULATIVE=1 -DEXP_VOTE=1"; do
  rm -rf /tmp/cap-q
  ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v" ORB_CAPTURE_SKIP=8 ORB_CAPTURE_PASS=/tmp/cap-q timeout 120 "$B/orb-render" $W/bench-1m.orb --width 1920 --height 1080 --device NVIDIA --benchmark --benchmark-seconds 1 2>&1 | grep -E "captured"
  timeout 150 $NCU --kernel-name regex:render_pass --launch-skip 1 --launch-count 1 --section WarpStateStats --section ComputeWorkloadAnalysis --section Occupancy \
    "$B/orb-cuda-replay" /tmp/cap-q --repeat 2 2>&1 | grep -E "Active Threads|Predicated|Achieved Occ|Issue Slots|floats equal|samples_per" | sed "s/^/[$v] /"
done
