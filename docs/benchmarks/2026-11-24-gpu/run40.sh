#!/usr/bin/env bash
# H100, 2026-11-24 (fifth session): where the wavefront prototype's time goes
# (orb-wavefront-benchmark now also times each kind of kernel over a few
# waves, each launch waited for, and counts the queues), and whether a
# higher register cap for its program helps (-cl-nv-maxrregcount after the
# renderer's own, with the register report to show which cap took).
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
  timeout 150 "$B/orb-wavefront-benchmark" "$@" --device NVIDIA --seconds 2 --rounds 1 2>&1 | tail -3
}
for p in 10 100k 1m; do wave "$p spheres, 1920x1080, 2 paths per pixel" $W/bench-$p.orb --paths-per-pixel 2; done
wave "cornell 640x480, 8 paths per pixel" scenes/cornell.scn --width 640 --height 480 --paths-per-pixel 8
for cap in 96 128 255; do
  wave "1m spheres, 2 paths per pixel, -cl-nv-maxrregcount=$cap" $W/bench-1m.orb --paths-per-pixel 2 --options "-cl-nv-maxrregcount=$cap"
  XDG_CACHE_HOME=$(mktemp -d) ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS="-cl-nv-verbose -cl-nv-maxrregcount=$cap" timeout 150 "$B/orb-wavefront-benchmark" $W/bench-1m.orb \
    --device NVIDIA --width 64 --height 64 --seconds 0.1 --rounds 1 2>&1 | grep -A2 -E "Function properties for wavefront_(shade|intersect)" | grep -E "registers|spill"
done
