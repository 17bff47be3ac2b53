#!/usr/bin/env bash
# H100, 2026-11-24: the -36 fault and the centre ray (run8: it needs the depth
# or id channel, whose pixel-centre ray render_pass casts after its sample
# loop on the first pass). Kernels from .gpu/kvar, EXP_CENTRE_MODE: 0 as on
# main, 1 the centre ray cast before the sample loop, 2 not cast at all.
# 1 k and 1 M spheres, 1920x1080, 2-second benchmarks, all passes.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
for p in 1k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
for p in 1k 1m; do
  for cap in 64 80 96 128; do
    for mode in 0 1 2; do
      echo -n "$p cap $cap centre mode $mode: "
      ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="-cl-nv-maxrregcount=$cap -DEXP_CENTRE_MODE=$mode" timeout 120 "$B/orb-render" --benchmark \
        $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
    done
  done
done
