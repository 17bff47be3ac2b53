#!/usr/bin/env bash
# H100, 2026-11-24 (eighth session): issue 9's "done when" measure, the
# cost per sample of the clouds against the Cornell box's, in one run:
# orb-render --benchmark at 1920x1080 of cornell.scn and the orb-gen.py
# scenes of 10, 100 k and 1 M spheres, defaults, two interleaved rounds
# (.gpu/b a Release build of d38a801 by scripts/gpu-bundle.sh).
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 10 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
for round in 1 2; do
  for s in scenes/cornell.scn $W/bench-10.orb $W/bench-100k.orb $W/bench-1m.orb; do
    echo -n "round $round $(basename $s) 1920x1080: "
    timeout 120 "$B/orb-render" --benchmark "$s" --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
  done
done
