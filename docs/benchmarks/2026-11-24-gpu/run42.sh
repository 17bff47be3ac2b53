#!/usr/bin/env bash
# H100, 2026-11-24 (fifth session): the wavefront prototype with path
# regeneration (a finished path hands its slot to the pixel's next sample,
# so the queues stay full; run41: one sample per slot per wave), 1 to 4
# slots per pixel, 10 to 1 M spheres and the Cornell box.
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
for p in 1m 100k 10; do
  for k in 1 2 4; do wave "$p spheres, 1920x1080, $k slots per pixel" $W/bench-$p.orb --paths-per-pixel $k; done
done
for k in 1 4; do wave "cornell 640x480, $k slots per pixel" scenes/cornell.scn --width 640 --height 480 --paths-per-pixel $k; done
