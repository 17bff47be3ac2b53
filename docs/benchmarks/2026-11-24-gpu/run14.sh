#!/usr/bin/env bash
# H100, 2026-11-24 (second session): cheap GPU traversal variants, each a -D switch in a copy of the
# kernels (.gpu/kvar through ORB_KERNEL_DIR), 1 M spheres at 1920x1080, ray
# casting alone and the megakernel, two interleaved rounds.
#   EXP_RESTRICT     the scene tables' kernel arguments declared restrict
#   EXP_WHILE        closest-hit traversal as while-while (nodes until a leaf, then the leaf)
#   EXP_SELF_PACKET  shadow rays test the packet of the sphere they leave first
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
[[ -e $W/bench-1m.orb ]] || python3 scripts/orb-gen.py --preset 1m -o $W/bench-1m.orb >/dev/null
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
variants=("" "-DEXP_RESTRICT" "-DEXP_WHILE" "-DEXP_SELF_PACKET" "-DEXP_RESTRICT -DEXP_WHILE -DEXP_SELF_PACKET")
for round in 1 2; do
  for v in "${variants[@]}"; do
    echo "== round $round trace_rays [$v]"
    ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v" timeout 120 "$B/orb-trace-benchmark" $W/bench-1m.orb --device NVIDIA --seconds 2 2>&1 | grep rays
  done
  for v in "${variants[@]}"; do
    echo -n "== round $round megakernel [$v]: "
    ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v" timeout 120 "$B/orb-render" --benchmark $W/bench-1m.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
  done
done
