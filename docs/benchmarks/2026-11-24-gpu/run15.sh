#!/usr/bin/env bash
# H100, 2026-11-24 (second session): ten million spheres on the GPU, 1920x1080:
# samples/s and device memory (--stats-json), wall time of a first image,
# beside 10 and 1 M spheres in the same run for the cost ratio.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 10 1m 10m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
echo -n "first image, 10m, 1920x1080 --spp 1: "
/usr/bin/time -f "wall %e s, max RSS %M kB" timeout 300 "$B/orb-render" $W/bench-10m.orb --device NVIDIA --width 1920 --height 1080 --spp 1 -o /tmp/f.exr -q --stats-json /tmp/f.json 2>&1 | tail -1
grep -E '"device_memory_bytes"' /tmp/f.json
for round in 1 2 3; do
  for p in 10 1m 10m; do
    echo -n "round $round $p: "
    timeout 300 "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q --stats-json /tmp/s-$p.json 2>&1 | tail -1
    grep -E '"device_memory_bytes"' /tmp/s-$p.json
  done
done
