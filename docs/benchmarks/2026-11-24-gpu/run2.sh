#!/usr/bin/env bash
# H100, 2026-11-24: traversal variants, each a -D switch in a copy of the
# kernels (.gpu/kvar, loaded through ORB_KERNEL_DIR; the patch is
# traversal-variants.patch beside this script): ray casting alone
# (orb-trace-benchmark) and the megakernel (orb-render --benchmark), 1 M
# spheres at 1920x1080, two interleaved rounds.
#   EXP_FMA             slab distances as fma(plane, 1/d, -o/d)
#   EXP_SHADOW_UNSORTED shadow rays visit hit children in lane order, unsorted
#   EXP_PACKED_STACK    closest-hit stack entries as one int2 (child, entry bits)
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
[[ -e $W/bench-1m.orb ]] || python3 scripts/orb-gen.py --preset 1m -o $W/bench-1m.orb >/dev/null
variants=("" "-DEXP_FMA=1" "-DEXP_SHADOW_UNSORTED=1" "-DEXP_PACKED_STACK=1" "-DEXP_FMA=1 -DEXP_SHADOW_UNSORTED=1 -DEXP_PACKED_STACK=1")
for round in 1 2; do
  for v in "${variants[@]}"; do
    echo "== round $round trace_rays [$v]"
    ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v" "$B/orb-trace-benchmark" $W/bench-1m.orb --device NVIDIA --seconds 2 2>&1 | grep rays
  done
  for v in "${variants[@]}"; do
    echo "== round $round megakernel [$v]"
    ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v" "$B/orb-render" --benchmark $W/bench-1m.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 3 -q 2>&1 | tail -1
  done
done
