#!/usr/bin/env bash
# H100, 2026-11-24 (fifth session): the wavefront prototype (run43's build)
# at larger waves and at 10 M spheres: does it pull ahead of the megakernel
# where the traversal's share is largest?
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 1m 10m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
wave() { # label args...
  local label=$1; shift
  echo "== $label"
  timeout 240 "$B/orb-wavefront-benchmark" "$@" --device NVIDIA --seconds 2 --rounds 2 2>&1 | tail -4 | cut -c1-400
}
wave "1m spheres, 1920x1080, 32 paths per pixel" $W/bench-1m.orb --paths-per-pixel 32
for k in 8 16 32; do wave "10m spheres, 1920x1080, $k paths per pixel" $W/bench-10m.orb --paths-per-pixel $k; done
