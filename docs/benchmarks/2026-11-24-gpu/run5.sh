#!/usr/bin/env bash
# H100, 2026-11-24: does the -36 fault come with non-finite rays? render_pass
# at register cap 128 (faults every time in run3/run4), kernels from .gpu/kvar
# (traversal-variants.patch plus two switches): EXP_REPORT_NONFINITE prints
# every closest-hit or shadow ray with a non-finite origin or direction,
# EXP_FINITE_SHADOW makes light_visible refuse such rays.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
for p in 1k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
C=-cl-nv-maxrregcount=128
for p in 1k 1m; do
  echo "== $p, reporting non-finite rays, --spp 16 render"
  ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$C -DEXP_REPORT_NONFINITE=1" timeout 120 "$B/orb-render" $W/bench-$p.orb --device NVIDIA \
    --width 1920 --height 1080 --spp 16 -o /tmp/x.exr -q 2>&1 | cut -c1-30 | sort | uniq -c | sort -rn | head -5
  echo "== $p, EXP_FINITE_SHADOW benchmark"
  ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$C -DEXP_FINITE_SHADOW=1" timeout 120 "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA \
    --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
  echo "== $p, plain kvar benchmark (control)"
  ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$C" timeout 120 "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA \
    --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
done
