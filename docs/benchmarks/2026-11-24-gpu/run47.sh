#!/usr/bin/env bash
# H100, 2026-11-24 (seventh session): the traversal stack's first S entries
# in __local (shared) memory instead of the private array (local memory),
# the development knob -DORB_BVH_SHARED_STACK=S of shared-stack.patch
# (beside this script, applied to ac490ae; .gpu/b a Release build of it by
# scripts/gpu-bundle.sh); S = 0 is main's code. NVIDIA's
# register report first, then the images of S = 0 and S = 16 compared, then
# the megakernel at 1920x1080 (1 k, 100 k, 1 M spheres) and ray casting
# alone (1 M), two interleaved rounds.
set -uo pipefail
python3 -m pip install -q --no-index --no-deps --no-compile --no-cache-dir --upgrade --target /tmp/site .whl/*.whl && export PYTHONPATH=/tmp/site
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 1k 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
sizes=(0 8 16 24 32)
for s in 0 16 32; do
  echo "== verbose S=$s"
  ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS="-DORB_BVH_SHARED_STACK=$s -cl-nv-verbose" timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 64 --height 64 --spp 1 -o /tmp/v.exr -q 2>&1 | grep -iE "render_pass|registers|spill|stack frame|smem|shared" | head -12
done
for s in 0 4 16; do
  ORB_CL_OPTIONS="-DORB_BVH_SHARED_STACK=$s" timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 640 --height 360 --spp 16 -o /tmp/img-$s.exr -q || echo "FAILED S=$s"
done
echo -n "relMSE S=4 against S=0: "; python3 scripts/exr-relmse.py /tmp/img-0.exr /tmp/img-4.exr
echo -n "relMSE S=16 against S=0: "; python3 scripts/exr-relmse.py /tmp/img-0.exr /tmp/img-16.exr
for round in 1 2; do
  for s in "${sizes[@]}"; do
    for p in 1m 100k 1k; do
      echo -n "round $round $p S=$s: "
      ORB_CL_OPTIONS="-DORB_BVH_SHARED_STACK=$s" timeout 120 "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
    done
  done
  for s in 0 16 32; do
    echo "== round $round trace_rays 1m S=$s"
    ORB_CL_OPTIONS="-DORB_BVH_SHARED_STACK=$s" timeout 120 "$B/orb-trace-benchmark" $W/bench-1m.orb --device NVIDIA --seconds 2 2>&1 | grep rays
  done
done
