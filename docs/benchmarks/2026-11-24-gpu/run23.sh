#!/usr/bin/env bash
# H100, 2026-11-24 (third session): would persistent threads with per-lane
# ray replacement (Aila and Laine 2009) cast the megakernel's kind of rays
# faster? Nsight Compute (run22) shows render_pass's traversal running at 9
# of 32 lanes for box visits and 2-3 for leaves at 1 M spheres. The kernel
# copy .gpu/kvar (kernels/ with persistent-trace.patch, which also adds the
# host knob ORB_TRACE_GROUPS) has trace_rays as a persistent kernel:
# groups of 128, each lane one visit per loop turn and a new ray from its
# group's counter as soon as its own is done. main's trace_rays beside it,
# two rounds, 100 k and 1 M spheres, 1920x1080 batches.
# Then Nsight Compute's details page for the tuned passes of run22.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
NCU=/usr/local/cuda/bin/ncu
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
for round in 1 2; do
  for p in 100k 1m; do
    echo "== round $round $p main"
    timeout 120 "$B/orb-trace-benchmark" $W/bench-$p.orb --device NVIDIA --seconds 1 2>&1 | grep "rays/s"
    for g in 1056 2112 4224; do
      echo "== round $round $p persistent, $g groups"
      ORB_TRACE_GROUPS=$g ORB_KERNEL_DIR=$K timeout 120 "$B/orb-trace-benchmark" $W/bench-$p.orb --device NVIDIA --seconds 1 2>&1 | grep "rays/s"
    done
  done
done
echo "== registers, persistent"
ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose ORB_KERNEL_DIR=$K ORB_TRACE_GROUPS=1056 timeout 60 "$B/orb-trace-benchmark" $W/bench-1m.orb --device NVIDIA --seconds 0.1 2>&1 | grep -E "stack frame|Used" | head -2
capture() {  # name, orb-render arguments
  local name=$1; shift
  rm -rf /tmp/cap-$name
  ORB_CAPTURE_SKIP=8 ORB_CAPTURE_PASS=/tmp/cap-$name timeout 120 "$B/orb-render" "$@" --device NVIDIA --benchmark --benchmark-seconds 1 2>&1 | grep -E "captured|samples_per"
}
capture cornell scenes/cornell.scn
capture m1 $W/bench-1m.orb --width 1920 --height 1080
for name in cornell m1; do
  timeout 200 $NCU --kernel-name regex:render_pass --launch-skip 1 --launch-count 1 --set full \
    "$B/orb-cuda-replay" /tmp/cap-$name --repeat 2 > $OUT/ncu-tuned-$name.txt 2>&1
  echo "ncu $name rc $?"
done
