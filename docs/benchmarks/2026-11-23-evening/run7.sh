#!/usr/bin/env bash
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
S=2
for p in 1k 1m; do python3 scripts/orb-gen.py --preset $p -o /tmp/orb-$p.orb >/dev/null; done
orb() { local b=$1; shift; LD_LIBRARY_PATH=$G/$b "$G/$b/orb-render" "$@"; }
bench() { local label=$1 b=$2; shift 2
  local out; out=$(orb $b --benchmark "$@" --device NVIDIA --benchmark-seconds $S -q 2>&1)
  local sps; sps=$(sed -n 's/.*samples_per_second=\([0-9.e+]*\).*/\1/p' <<<"$out" | tail -1)
  printf '%-52s %s\n' "$label" "${sps:-failed: $(tail -c 60 <<<"$out" | tr '\n' ' ')}"; }
for r in 1 2 3 4 5 6; do
  for p in 1k 1m; do A="/tmp/orb-$p.orb --width 1920 --height 1080"
  bench "r$r $p main" main $A
  ORB_KERNEL_DIR=$G/kquiet ORB_CL_OPTIONS=-DORB_BVH_CHECK=1 bench "r$r $p quiet checks" main $A
  ORB_KERNEL_DIR=$G/kpacket bench "r$r $p packet variant" main $A
  ORB_KERNEL_DIR=$G/kstack bench "r$r $p stack 128" main $A
  done
done
