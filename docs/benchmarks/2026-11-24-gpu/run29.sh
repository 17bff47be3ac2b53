#!/usr/bin/env bash
# H100, 2026-11-24 (third session): the long-scoreboard stalls of run22's
# profile (34% at 1 M spheres) wait on node bounds, on the child indices
# (loaded after the slab tests), on the stack, and on each leaf sphere's
# radius, whose padding test comes before the centre's loads. Variants in
# .gpu/kvar = kernels/ of 8c8b51d with load-order.patch:
#   leaf1   -DEXP_LEAF_LOADS=1: a lane's four numbers loaded before its test
#   leaf2   -DEXP_LEAF_LOADS=2: the packet's sixteen numbers loaded first
#   child   -DEXP_CHILD_FIRST: a node's child indices loaded with its bounds
# Images bit-identical on PoCL. Two rounds.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 10 1k 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
bench() {  # label, options, scene args...
  local label=$1 options=$2; shift 2
  echo -n "$label: "
  ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$options" timeout 120 "$B/orb-render" --benchmark "$@" --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
}
for round in 1 2; do
  for scene in "scenes/cornell.scn" "$W/bench-10.orb --width 1920 --height 1080" "$W/bench-1k.orb --width 1920 --height 1080" "$W/bench-100k.orb --width 1920 --height 1080" "$W/bench-1m.orb --width 1920 --height 1080"; do
    echo "== round $round $scene"
    bench main "" $scene
    bench leaf1 "-DEXP_LEAF_LOADS=1" $scene
    bench leaf2 "-DEXP_LEAF_LOADS=2" $scene
    bench child "-DEXP_CHILD_FIRST" $scene
    bench leaf1+child "-DEXP_LEAF_LOADS=1 -DEXP_CHILD_FIRST" $scene
  done
done
