#!/usr/bin/env bash
# H100, 2026-11-24: the -36 fault, continued (cap 128, 1 k spheres,
# 2-second benchmarks; kernels from .gpu/kvar where a switch of
# traversal-variants.patch is named).
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
[[ -e $W/bench-1k.orb ]] || python3 scripts/orb-gen.py --preset 1k -o $W/bench-1k.orb >/dev/null
bench() {  # label, kernel dir ("" = embedded), extra CL options, width, height, orb-render options...
  local label=$1 kdir=$2 opts=$3 width=$4 height=$5; shift 5
  echo -n "$label: "
  ORB_KERNEL_DIR=$kdir ORB_CL_OPTIONS="$opts" timeout 120 "$B/orb-render" --benchmark $W/bench-1k.orb --device NVIDIA \
    --width $width --height $height --benchmark-seconds 2 -q "$@" 2>&1 | tail -1
}
C=-cl-nv-maxrregcount=128
bench "independent, max-depth 2" "" "$C" 1920 1080 --sampler independent --max-depth 2
bench "independent, max-depth 3" "" "$C" 1920 1080 --sampler independent --max-depth 3
bench "sobol blocks 8" "" "$C -DORB_SOBOL_BLOCKS=8" 1920 1080
bench "sobol blocks 8, max-depth 8" "" "$C -DORB_SOBOL_BLOCKS=8" 1920 1080 --max-depth 8
bench "independent numbers initialised in Sobol blocks" "$K" "$C -DEXP_INIT_INDEPENDENT=1" 1920 1080
bench "kvar, nothing switched (control)" "$K" "$C" 1920 1080
for size in 96 128 160 192; do bench "${size}x${size}" "" "$C" $size $size; done
