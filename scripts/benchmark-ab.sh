#!/usr/bin/env bash
# Interleaved A/B benchmark of orb-render builds on one machine, for
# docs/performance.md: runs `orb-render --benchmark` of each build in turn,
# ORB_AB_RUNS rounds (default 3), so that load from other jobs on a shared
# machine falls on every build alike. Prints one line per run and the load.
#   scripts/benchmark-ab.sh NAME=BIN_DIR [NAME=BIN_DIR ...] -- [orb-render arguments]
# e.g.
#   scripts/benchmark-ab.sh before=/tmp/orb-before/build/bin after=build/bin -- \
#       --benchmark scenes/cornell.json --width 640 --height 480
set -euo pipefail
builds=()
while [[ $# -gt 0 && $1 != -- ]]; do builds+=("$1"); shift; done
[[ $# -gt 0 ]] && shift
[[ ${#builds[@]} -gt 0 && $# -gt 0 ]] || { echo "usage: $0 NAME=BIN_DIR... -- ORB_RENDER_ARGS" >&2; exit 2; }
runs=${ORB_AB_RUNS:-3}
for round in $(seq 1 "$runs"); do
  for build in "${builds[@]}"; do
    name=${build%%=*} bin=${build#*=}
    result=$("$bin/orb-render" "$@" 2>&1 | grep -o 'samples_per_second=[0-9.]*')
    echo "round $round $name ${result#samples_per_second=} load $(cut -d' ' -f1 /proc/loadavg)"
  done
done
