#!/usr/bin/env bash
# H100, 2026-11-24: the -36 fault against the paths' depth. render_pass at
# register cap 128 (faulted every time at the default depth 6 in run4),
# 2-second benchmarks of the 1 k-sphere cloud at 1920x1080.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
[[ -e $W/bench-1k.orb ]] || python3 scripts/orb-gen.py --preset 1k -o $W/bench-1k.orb >/dev/null
bench() {  # label, extra CL options, image width, height, orb-render options...
  local label=$1 opts=$2 width=$3 height=$4; shift 4
  echo -n "$label: "
  ORB_CL_OPTIONS="$opts" timeout 120 "$B/orb-render" --benchmark $W/bench-1k.orb --device NVIDIA --width $width --height $height \
    --benchmark-seconds 2 -q "$@" 2>&1 | tail -1
}
C=-cl-nv-maxrregcount=128
for depth in 2 3 4 5 6 8 12; do bench "cap128 max-depth $depth" "$C" 1920 1080 --max-depth $depth; done
bench "cap128 no roulette (RR_START_EVENT=100)" "$C -DRR_START_EVENT=100" 1920 1080
bench "cap128 old roulette (RR_THRESHOLD=1.0f)" "$C -DRR_THRESHOLD=1.0f" 1920 1080
bench "cap128 max-depth 6, 64x64" "$C" 64 64
bench "cap128 max-depth 6, 256x256" "$C" 256 256
for seed in 1 2 3; do bench "cap128 seed $seed" "$C" 1920 1080 --seed $seed; done
