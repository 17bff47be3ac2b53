#!/usr/bin/env bash
# H100, 2026-11-24 (second session): where the megakernel's time goes, by
# doing one part twice. In a copy of the kernels (.gpu/kvar):
#   EXP_TWICE_CLOSEST  every closest-hit tree traversal done twice
#   EXP_TWICE_SHADOW   every shadow ray cast twice
# the second on a direction equal to the first's but made to depend on its
# result through a volatile zero, so the compiler cannot merge them; the
# images stay the same. The slowdown is that part's cost in place.
# 10, 100 k and 1 M spheres at 1920x1080, two rounds.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 10 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
for round in 1 2; do
  for p in 10 100k 1m; do
    for v in "" "-DEXP_TWICE_CLOSEST" "-DEXP_TWICE_SHADOW"; do
      echo -n "round $round $p [$v]: "
      ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v" timeout 120 "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
    done
  done
done
for v in "" "-DEXP_TWICE_CLOSEST" "-DEXP_TWICE_SHADOW"; do
  echo "== registers [$v], 1m"
  ORB_SHOW_BUILD_LOG=1 ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v -cl-nv-verbose" timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 64 --height 64 --spp 1 -o /tmp/v.exr -q 2>&1 | grep -E "stack frame|Used" | head -2
done
