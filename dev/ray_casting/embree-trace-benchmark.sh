#!/usr/bin/env bash
# Orb's traversal beside Intel Embree's on the same rays, spheres and
# machine: orb-trace-benchmark casts its three batches (camera rays, a
# diffuse bounce from each hit, a shadow ray from each hit to a light) and
# dumps them with its answers; embree-trace-benchmark.cpp (beside this) casts the
# same rays with Embree 3 (Debian's libembree-dev, installed if missing)
# and says how many answers differ. The two alternate for ROUNDS rounds.
#
#   dev/ray_casting/embree-trace-benchmark.sh SCENE [WIDTH HEIGHT [ROUNDS [SECONDS]]]
#   dev/ray_casting/embree-trace-benchmark.sh /tmp/bench-100k.orb 640 360 2
#
# Embree runs on as many threads as PoCL has cores (nproc). ORB_TRACE_BENCHMARK
# names Orb's binary (default: build/bin/orb-trace-benchmark, built with
# -DORB_BUILD_DEV=ON). An idle machine only: both report wall-clock rates.
set -euo pipefail
if [[ $# -lt 1 ]]; then
  sed -n '2,14p' "$0" >&2
  exit 2
fi
scene=$1
width=${2:-640}
height=${3:-360}
rounds=${4:-2}
seconds=${5:-2}
here=$(cd "$(dirname "$0")" && pwd)
orb=${ORB_TRACE_BENCHMARK:-$here/../../build/bin/orb-trace-benchmark}
if [[ ! -e /usr/include/embree3/rtcore.h ]]; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q libembree-dev >/dev/null
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

g++ -std=c++20 -O3 -march=native -o "$work/embree-trace-benchmark" "$here/embree-trace-benchmark.cpp" -lembree3 -lpthread
mkdir "$work/rays"
echo "== $scene, ${width}x${height}, $(nproc) threads"
for round in $(seq 1 "$rounds"); do
  echo "-- round $round: Orb"
  dump=()
  [[ $round -eq 1 ]] && dump=(--dump "$work/rays")  # Embree casts the first round's rays
  # The three batches as cast; not their sorted and shuffled variants.
  "$orb" "$scene" --width "$width" --height "$height" --seconds "$seconds" "${dump[@]}" | grep -vE 'sorted|shuffled'
  echo "-- round $round: Embree"
  "$work/embree-trace-benchmark" "$work/rays" --threads "$(nproc)" --seconds "$seconds"
  "$work/embree-trace-benchmark" "$work/rays" --threads "$(nproc)" --seconds "$seconds" --split | tail -n +2 | sed 's/^/split: /'
done
