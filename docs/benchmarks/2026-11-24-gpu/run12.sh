#!/usr/bin/env bash
# H100, 2026-11-24: leaf runs (a node whose children are all leaves tests
# their packets without the boxes; on by default on CPUs) forced on for the
# GPU variant, against the GPU default (off): casting alone and the
# megakernel, 100 k and 1 M spheres, 1920x1080, two interleaved rounds.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
for p in 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
for round in 1 2; do
  for runs in 0 1; do
    for p in 100k 1m; do
      echo "== round $round leaf runs $runs $p"
      ORB_CL_OPTIONS=-DORB_BVH_LEAF_RUNS=$runs "$B/orb-trace-benchmark" $W/bench-$p.orb --device NVIDIA --seconds 2 2>&1 | grep "rays:"
      echo -n "megakernel: "
      ORB_CL_OPTIONS=-DORB_BVH_LEAF_RUNS=$runs timeout 120 "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA \
        --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
    done
  done
done
