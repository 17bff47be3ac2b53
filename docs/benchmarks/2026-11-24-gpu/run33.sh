#!/usr/bin/env bash
# H100, 2026-11-24 (fourth session): path regeneration against nested loops
# (each thread's samples one after another, a warp's lanes at the same
# bounce of neighbouring pixels) at 10 to 1 M spheres and on the Cornell
# box. Kernels: a copy of kernels/ with `#if EXP_NESTED` around render_pass's
# sample loop (.gpu/kvar); the films are bit-identical on PoCL.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 10 1k 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
export ORB_KERNEL_DIR=$PWD/.gpu/kvar
for round in 1 2; do
  for nested in 0 1; do
    echo -n "round $round nested=$nested cornell: "
    ORB_CL_OPTIONS=-DEXP_NESTED=$nested timeout 120 "$B/orb-render" --benchmark scenes/cornell.scn --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
    for p in 10 1k 100k 1m; do
      echo -n "round $round nested=$nested $p: "
      ORB_CL_OPTIONS=-DEXP_NESTED=$nested timeout 120 "$B/orb-render" --benchmark $W/bench-$p.orb --width 1920 --height 1080 --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
    done
  done
done
