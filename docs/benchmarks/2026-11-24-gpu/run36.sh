#!/usr/bin/env bash
# H100, 2026-11-24 (fourth session): the Cornell box with today's build by
# default, with the independent sampler, and with the independent sampler and
# the old roulette (threshold 1, -DRR_THRESHOLD=1.0f): the settings under
# which issue 9's 4.7 G samples/s floor was measured.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for round in 1 2; do
  for size in "640 480" "1920 1080"; do
    set -- $size
    echo -n "round $round ${1}x$2 default: "; timeout 120 "$B/orb-render" --benchmark scenes/cornell.scn --width $1 --height $2 --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
    echo -n "round $round ${1}x$2 independent: "; timeout 120 "$B/orb-render" --benchmark scenes/cornell.scn --width $1 --height $2 --sampler independent --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
    echo -n "round $round ${1}x$2 independent, old roulette: "; ORB_CL_OPTIONS=-DRR_THRESHOLD=1.0f timeout 120 "$B/orb-render" --benchmark scenes/cornell.scn --width $1 --height $2 --sampler independent --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
  done
done
