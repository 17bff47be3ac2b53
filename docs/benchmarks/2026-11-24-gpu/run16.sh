#!/usr/bin/env bash
# H100, 2026-11-24 (second session): the traversal as real calls in the
# megakernel. traverse_bvh (closest hits) and light_visible (shadow rays)
# marked __attribute__((noinline)) in a copy of the kernels (.gpu/kvar), so
# that their loops get registers of their own instead of sharing the cap
# with render_pass's live path state. 1 M and 100 k spheres, 1920x1080, the
# register cap swept; NVIDIA's report of registers and spills first.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
variants=("" "-DEXP_NOINLINE_TRAVERSE -DEXP_NOINLINE_SHADOW" "-DEXP_NOINLINE_TRAVERSE" "-DEXP_NOINLINE_SHADOW")
for v in "${variants[@]}"; do
  for cap in 64 96; do
    echo "== verbose [$v] cap $cap"
    ORB_SHOW_BUILD_LOG=1 ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v -cl-nv-maxrregcount=$cap -cl-nv-verbose" timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 64 --height 64 --spp 1 -o /tmp/v.exr -q 2>&1 | grep -iE "render_pass|registers|spill|stack frame" | head -12
  done
done
for round in 1 2; do
  for v in "${variants[@]}"; do
    for cap in 64 96 128; do
      for p in 1m 100k; do
        echo -n "round $round $p cap $cap [$v]: "
        ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v -cl-nv-maxrregcount=$cap" timeout 120 "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
      done
    done
  done
done
