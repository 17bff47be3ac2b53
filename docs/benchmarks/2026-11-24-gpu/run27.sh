#!/usr/bin/env bash
# H100, 2026-11-24 (third session): cost per sample against sphere count at
# 1920x1080 with the final build of the session (speculative traversal,
# numbers drawn before the branches), the plot for docs/performance.md.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
python3 scripts/bench-scaling.py --presets 10 1k 100k 1m 10m --width 1920 --height 1080 --rounds 2 --seconds 2 \
  --bin "$PWD/.gpu/b" --work /tmp/orb-scenes --orb-args "--device NVIDIA" --svg "$OUT/scaling-h100.svg"
