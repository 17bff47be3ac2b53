#!/usr/bin/env bash
# GPU node (16 cores), 2026-11-24 (fourth session): the first image of
# 10 M spheres after the BVH builder's fix (a split cutting off the lamps no
# longer leaves the cloud to one thread), and the build against threads.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
nproc
for p in 1m 10m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
for t in 1 2 4 8 16; do "$B/orb-bvh-benchmark" --scene $W/bench-10m.orb $t | tail -1; done
"$B/orb-bvh-benchmark" --scene $W/bench-1m.orb | tail -1
for i in 1 2; do
  /usr/bin/time -f "wall %e s, max rss %M KB" "$B/orb-render" $W/bench-10m.orb --device NVIDIA --width 1920 --height 1080 --spp 1 -o /tmp/r.exr 2>&1 | grep -E "ready|wall|done"
done
