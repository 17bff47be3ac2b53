#!/usr/bin/env bash
# How much tree traversal one sample costs: renders SCENE once with the
# kernels' visit counters on (-DORB_BVH_COUNT=1, kernels/intersect.cl) and
# sums what they print: rays that entered the tree per sample, and nodes and
# leaves visited per ray, for closest hits and for shadow rays.
#
#   scripts/bvh-visits.sh SCENE [WIDTH HEIGHT SPP [orb-render options...]]
#   scripts/bvh-visits.sh /tmp/bench-100k.orb 64 48 1 --mode direct
#
# Every ray prints one line, so keep the image small (the default is 64x48
# at 1 spp). Only the beauty layer is rendered, so no centre ray per pixel
# is counted. ORB_RENDER names the binary (default: build/bin/orb-render).
set -euo pipefail
if [[ $# -lt 1 ]]; then
  sed -n '2,12p' "$0" >&2
  exit 2
fi
scene=$1
width=${2:-64}
height=${3:-48}
spp=${4:-1}
shift $(( $# < 4 ? $# : 4 ))
render=${ORB_RENDER:-$(dirname "$0")/../build/bin/orb-render}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

ORB_CL_OPTIONS="${ORB_CL_OPTIONS:-} -DORB_BVH_COUNT=1" "$render" "$scene" --width "$width" --height "$height" \
  --spp "$spp" --passes beauty -o "$work/image.exr" -q "$@" >"$work/visits.txt"
awk -v samples=$((width * height * spp)) '
  $1 == "orb" && $2 == "BVH" && $3 == "visits:" { rays[$4]++; visits[$4] += $5 }
  END {
    if (!("closest" in rays)) { print "no ray entered a tree (a scene too small for one?)"; exit 1 }
    total = 0
    printf "samples: %d\n", samples
    for (kind in rays) {
      printf "%s rays per sample: %.3f, visits per ray: %.2f\n", kind, rays[kind] / samples, visits[kind] / rays[kind]
      total += visits[kind]
    }
    printf "visits per sample: %.2f\n", total / samples
  }' "$work/visits.txt"
