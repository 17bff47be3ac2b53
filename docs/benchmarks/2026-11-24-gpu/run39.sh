#!/usr/bin/env bash
# H100, 2026-11-24 (fifth session): the wavefront prototype
# (orb-wavefront-benchmark: kernels/wavefront.cl against render_pass, side by
# side in one process) at 10 to 1 M spheres and on the Cornell box, with one
# and more paths per pixel per wave, and NVIDIA's register report for the
# wavefront kernels (a fresh binary cache, so that the program is compiled
# and its log printed).
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
  timeout 150 "$B/orb-wavefront-benchmark" "$@" --device NVIDIA --seconds 2 --rounds 2 2>&1 | tail -3
}
for p in 10 100k 1m; do
  for k in 1 2; do wave "$p spheres, 1920x1080, $k paths per pixel" $W/bench-$p.orb --paths-per-pixel $k; done
done
wave "cornell 640x480, 1 path per pixel" scenes/cornell.scn --width 640 --height 480 --paths-per-pixel 1
wave "cornell 640x480, 8 paths per pixel" scenes/cornell.scn --width 640 --height 480 --paths-per-pixel 8
echo "== registers (1 M spheres, then the Cornell box)"
for s in $W/bench-1m.orb scenes/cornell.scn; do
  XDG_CACHE_HOME=$(mktemp -d) ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose timeout 150 "$B/orb-wavefront-benchmark" $s \
    --device NVIDIA --width 64 --height 64 --seconds 0.1 --rounds 1 2>&1 | grep -iE "Function properties for|registers|spill|stack frame" | head -30
done
