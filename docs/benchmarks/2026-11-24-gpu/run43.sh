#!/usr/bin/env bash
# H100, 2026-11-24 (fifth session): the wavefront prototype in waves (no
# regeneration, as run41) with its path state in four float4 words instead
# of six (from_point and from_self are the ray's origin and self; the flags
# packed with the depth; the pixel from the slot), and larger waves: 2 to
# 16 paths per pixel.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 10 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
wave() { # label args...
  local label=$1; shift
  echo "== $label"
  timeout 150 "$B/orb-wavefront-benchmark" "$@" --device NVIDIA --seconds 2 --rounds 2 2>&1 | tail -4 | cut -c1-400
}
for k in 2 4 8 16; do wave "1m spheres, 1920x1080, $k paths per pixel" $W/bench-1m.orb --paths-per-pixel $k; done
for p in 100k 10; do
  for k in 4 8; do wave "$p spheres, 1920x1080, $k paths per pixel" $W/bench-$p.orb --paths-per-pixel $k; done
done
for k in 8 16; do wave "cornell 640x480, $k paths per pixel" scenes/cornell.scn --width 640 --height 480 --paths-per-pixel $k; done
