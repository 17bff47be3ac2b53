#!/usr/bin/env bash
# GPU node (16 cores), 2026-11-24 (fourth session): the tree build with the
# top levels' bounds and bins computed in chunks on the spare threads
# (orb-bvh-benchmark) against the build before it (orb-bvh-benchmark-old),
# interleaved, 10 M and 1 M spheres, 16 and 2 threads.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nproc
for p in 1m 10m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
for round in 1 2; do
  for t in 16 2; do
    for v in old new; do
      b="$B/orb-bvh-benchmark"; [[ $v == old ]] && b="$B/orb-bvh-benchmark-old"
      echo -n "round $round $v threads $t 10m: "; "$b" --scene $W/bench-10m.orb $t | tail -1
      echo -n "round $round $v threads $t 1m: "; "$b" --scene $W/bench-1m.orb $t | tail -1
    done
  done
done
