#!/usr/bin/env bash
# H100, 2026-11-24, after the review: the traversal's leaf-run branch
# restructured (no goto, its packets bounds-checked) must leave the GPU
# variant as it was: speed and no fault, 1920x1080.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
for p in 10 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
for round in 1 2 3; do
  for p in 10 100k 1m; do
    echo -n "round $round $p: "
    timeout 120 "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
  done
done
echo -n "cornell 640x480: "
timeout 120 "$B/orb-render" --benchmark scenes/cornell.scn --device NVIDIA --benchmark-seconds 2 -q 2>&1 | tail -1
echo -n "render 1m --spp 64, all passes: "
timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 1920 --height 1080 --spp 64 -o /tmp/r.exr -q 2>&1 | tail -1
echo "(exit $?)"
