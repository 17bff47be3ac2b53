#!/usr/bin/env bash
# H100, 2026-11-24 (third session): the final build (speculative traversal,
# numbers drawn before the branches) rendering to completion, every layer,
# several times: the -36 kernel fault of 2026-11-23 came with code shapes
# of the traversal, so look for it. Five 64-spp renders each of 1 k, 100 k
# and 1 M spheres at 1920x1080 and one of 10 M, exit codes and the error
# line if any.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 1k 100k 1m 10m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
faults=0
for p in 1k 100k 1m; do
  for i in 1 2 3 4 5; do
    out=$(timeout 200 "$B/orb-render" $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --spp 64 --seed $i -o /tmp/r.exr -q 2>&1); rc=$?
    echo "$p seed $i: rc $rc $out"
    [[ $rc -ne 0 ]] && faults=$((faults + 1))
  done
done
out=$(timeout 300 "$B/orb-render" $W/bench-10m.orb --device NVIDIA --width 1920 --height 1080 --spp 16 -o /tmp/r.exr -q 2>&1); rc=$?
echo "10m: rc $rc $out"; [[ $rc -ne 0 ]] && faults=$((faults + 1))
echo "failed renders: $faults of 16"
