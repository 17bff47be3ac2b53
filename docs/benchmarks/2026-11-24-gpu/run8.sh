#!/usr/bin/env bash
# H100, 2026-11-24: the -36 fault against the film channels built (cap 128,
# 1 k spheres, 1920x1080, 2-second benchmarks; beauty alone ran in run4).
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
[[ -e $W/bench-1k.orb ]] || python3 scripts/orb-gen.py --preset 1k -o $W/bench-1k.orb >/dev/null
C=-cl-nv-maxrregcount=128
for passes in beauty beauty,direct beauty,indirect beauty,emission beauty,albedo beauty,normal beauty,depth beauty,variance beauty,id all; do
  echo -n "--passes $passes: "
  ORB_CL_OPTIONS="$C" timeout 120 "$B/orb-render" --benchmark $W/bench-1k.orb --device NVIDIA --width 1920 --height 1080 \
    --benchmark-seconds 2 -q --passes $passes 2>&1 | tail -1
done
echo -n "render --spp 1, all passes: "
ORB_CL_OPTIONS="$C" timeout 120 "$B/orb-render" $W/bench-1k.orb --device NVIDIA --width 1920 --height 1080 --spp 1 -o /tmp/x.exr -q 2>&1 | tail -1; echo "(exit $?)"
echo -n "render --spp 4, all passes: "
ORB_CL_OPTIONS="$C" timeout 120 "$B/orb-render" $W/bench-1k.orb --device NVIDIA --width 1920 --height 1080 --spp 4 -o /tmp/x.exr -q 2>&1 | tail -1; echo "(exit $?)"
