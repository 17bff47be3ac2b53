#!/usr/bin/env bash
# H100, 2026-11-24: the -36 fault against render_pass's stack frame. For each
# register cap (and the packed-stack variant of run2, which faulted in every
# run at the host's cap of 96), NVIDIA's build report for render_pass
# (registers, stack frame, spills) and whether a 2-second benchmark of the
# 1 M-sphere cloud at 1920x1080 faults.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
[[ -e $W/bench-1m.orb ]] || python3 scripts/orb-gen.py --preset 1m -o $W/bench-1m.orb >/dev/null
try() {
  echo "== [$1]"
  ORB_KERNEL_DIR=$K ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS="-cl-nv-verbose $1" "$B/orb-render" --benchmark $W/bench-1m.orb \
    --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 |
    grep -A2 "Function properties for render_pass" | grep -vE "^--" ; 
  ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$1" "$B/orb-render" --benchmark $W/bench-1m.orb \
    --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
}
for cap in 64 72 80 96 112 128 160; do try "-cl-nv-maxrregcount=$cap"; done
try "-cl-nv-maxrregcount=96 -DEXP_PACKED_STACK=1"
try "-cl-nv-maxrregcount=128 -DEXP_PACKED_STACK=1"
try "-cl-nv-maxrregcount=160 -DEXP_PACKED_STACK=1"
