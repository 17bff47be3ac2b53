#!/usr/bin/env bash
# H100, 2026-11-24 (second session): next-event estimation's shadow ray
# deferred to the next turn of render_pass's loop and cast through the same
# call site as the path's rays (-DEXP_DEFER_SHADOW in a copy of the kernels,
# .gpu/kvar; on PoCL its images are bit-identical to main's). 10, 100 k and
# 1 M spheres at 1920x1080 and the Cornell box at 640x480, two rounds; the
# images of both at 1 M spheres come back for orb-diff; a 64-spp render of
# every pass as a fault check.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 10 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
for round in 1 2; do
  for v in "" "-DEXP_DEFER_SHADOW"; do
    for p in 10 100k 1m; do
      echo -n "round $round $p [$v]: "
      ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v" timeout 120 "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
    done
    echo -n "round $round cornell 640x480 [$v]: "
    ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v" timeout 120 "$B/orb-render" --benchmark scenes/cornell.scn --device NVIDIA --benchmark-seconds 2 -q 2>&1 | tail -1
  done
done
for v in "" "-DEXP_DEFER_SHADOW"; do
  echo "== registers [$v], 1m / cornell"
  ORB_SHOW_BUILD_LOG=1 ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v -cl-nv-verbose" timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 64 --height 64 --spp 1 -o /tmp/v.exr -q 2>&1 | grep -E "stack frame|Used" | head -2
  ORB_SHOW_BUILD_LOG=1 ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$v -cl-nv-verbose" timeout 120 "$B/orb-render" scenes/cornell.scn --device NVIDIA --width 64 --height 64 --spp 1 -o /tmp/v.exr -q 2>&1 | grep -E "stack frame|Used" | head -2
done
echo "== images, 1m 640x360 16 spp, every pass"
ORB_KERNEL_DIR=$K timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 640 --height 360 --spp 16 -o ${OUT:-/tmp}/main-1m.exr -q; echo "main exit $?"
ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="-DEXP_DEFER_SHADOW" timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 640 --height 360 --spp 16 -o ${OUT:-/tmp}/defer-1m.exr -q; echo "defer exit $?"
ORB_KERNEL_DIR=$K timeout 120 "$B/orb-render" scenes/cornell.scn --device NVIDIA --spp 16 -o ${OUT:-/tmp}/main-cornell.exr -q; echo "main exit $?"
ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="-DEXP_DEFER_SHADOW" timeout 120 "$B/orb-render" scenes/cornell.scn --device NVIDIA --spp 16 -o ${OUT:-/tmp}/defer-cornell.exr -q; echo "defer exit $?"
echo "== fault check: 1m 1920x1080 64 spp every pass, three times"
for k in 1 2 3; do ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="-DEXP_DEFER_SHADOW" timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 1920 --height 1080 --spp 64 -o /tmp/f.exr -q; echo "exit $?"; done
