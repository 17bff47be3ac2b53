#!/usr/bin/env bash
# H100, 2026-11-24 (fourth session): would sorting a wavefront renderer's
# rays pay? orb-trace-benchmark casts bounce and shadow rays in pixel order,
# sorted by direction octant and origin Morton code, and shuffled, at 100 k
# and 1 M spheres, 1920x1080 camera rays' hits.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
for round in 1 2; do
  for p in 100k 1m; do
    echo "== round $round trace_rays $p"
    timeout 200 "$B/orb-trace-benchmark" $W/bench-$p.orb --device NVIDIA --seconds 1.5 2>&1
  done
done
