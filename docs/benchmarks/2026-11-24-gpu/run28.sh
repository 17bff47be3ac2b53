#!/usr/bin/env bash
# H100, 2026-11-24 (third session): shadow rays without sorting a node's
# hit children (any order will do for an any-hit ray), in the speculative
# traversal. .gpu/kvar = kernels/ of 8c8b51d with shadow-unsorted.patch,
# -DEXP_SHADOW_UNSORTED. 1 k, 100 k and 1 M spheres at 1920x1080, two rounds.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 1k 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
bench() {  # label, options, scene args...
  local label=$1 options=$2; shift 2
  echo -n "$label: "
  ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$options" timeout 120 "$B/orb-render" --benchmark "$@" --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
}
for round in 1 2; do
  for p in 1k 100k 1m; do
    echo "== round $round $p"
    bench sorted "" $W/bench-$p.orb --width 1920 --height 1080
    bench unsorted "-DEXP_SHADOW_UNSORTED" $W/bench-$p.orb --width 1920 --height 1080
  done
done
