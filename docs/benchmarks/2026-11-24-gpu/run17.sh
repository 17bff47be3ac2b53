#!/usr/bin/env bash
# H100, 2026-11-24 (second session): 64-byte quantized 4-wide nodes on the
# GPU (prototype: the host quantizes each child plane to 8 bits in steps of
# a power of two from the node's corner, with ORB_EXP_QNODES=1; the kernels
# in .gpu/kvar decode them with -DEXP_QNODES, and with -DEXP_QFMA fold the
# decode into one fma per plane). 1 M and 100 k spheres, 1920x1080, casting
# alone and the megakernel, two interleaved rounds.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
K=$PWD/.gpu/kvar
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
run() {  # label, env for the host (or empty), kernel options
  local label=$1 hostenv=$2 opts=$3 p
  for p in 1m 100k; do
    echo "== $label $p trace_rays"
    env $hostenv ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$opts" timeout 120 "$B/orb-trace-benchmark" $W/bench-$p.orb --device NVIDIA --seconds 2 2>&1 | grep "rays/s"
    echo -n "== $label $p megakernel: "
    env $hostenv ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="$opts" timeout 120 "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
  done
}
for round in 1 2; do
  run "round $round main" "ORB_NOTHING=1" ""
  run "round $round qnodes" "ORB_EXP_QNODES=1" "-DEXP_QNODES"
  run "round $round qnodes+fma" "ORB_EXP_QNODES=1" "-DEXP_QNODES -DEXP_QFMA"
done
echo -n "image check, 1m 640x360 8 spp, main vs qnodes: "
timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 640 --height 360 --spp 8 -o ${OUT:-/tmp}/m.exr -q --passes beauty
ORB_EXP_QNODES=1 ORB_KERNEL_DIR=$K ORB_CL_OPTIONS="-DEXP_QNODES" timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 640 --height 360 --spp 8 -o ${OUT:-/tmp}/q.exr -q --passes beauty
echo "(compared with orb-diff after the run)"
