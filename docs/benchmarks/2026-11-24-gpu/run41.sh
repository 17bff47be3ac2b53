#!/usr/bin/env bash
# H100, 2026-11-24 (fifth session): the wavefront prototype with its path
# state as structure-of-arrays float4 words (run39-40: array of structs),
# per-kernel times and queue lengths, 10 to 1 M spheres and the Cornell box.
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
  timeout 150 "$B/orb-wavefront-benchmark" "$@" --device NVIDIA --seconds 2 --rounds 2 2>&1 | tail -4
}
for p in 10 100k 1m; do wave "$p spheres, 1920x1080, 2 paths per pixel" $W/bench-$p.orb --paths-per-pixel 2; done
wave "1m spheres, 1920x1080, 4 paths per pixel" $W/bench-1m.orb --paths-per-pixel 4
wave "cornell 640x480, 8 paths per pixel" scenes/cornell.scn --width 640 --height 480 --paths-per-pixel 8
XDG_CACHE_HOME=$(mktemp -d) ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS="-cl-nv-verbose" timeout 150 "$B/orb-wavefront-benchmark" $W/bench-1m.orb \
  --device NVIDIA --width 64 --height 64 --seconds 0.1 --rounds 1 2>&1 | grep -A2 -E "Function properties for wavefront_" | grep -E "properties|registers|spill"
