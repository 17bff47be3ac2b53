#!/usr/bin/env bash
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
S=${S:-2}
for p in 1k 1m; do python3 scripts/orb-gen.py --preset $p -o /tmp/orb-$p.orb >/dev/null || echo "gen $p failed"; done
orb() { local b=$1; shift; LD_LIBRARY_PATH=$G/$b "$G/$b/orb-render" "$@"; }
bench() { local label=$1 b=$2; shift 2
  local out; out=$(orb $b --benchmark "$@" --device NVIDIA --benchmark-seconds $S -q 2>&1)
  local sps; sps=$(sed -n 's/.*samples_per_second=\([0-9.e+]*\).*/\1/p' <<<"$out" | tail -1)
  printf '%-52s %s\n' "$label" "${sps:-failed: $(tail -c 200 <<<"$out" | tr '\n' ' ')}"; }
A="/tmp/orb-1k.orb --width 1920 --height 1080"
for r in 1 2; do
bench "r$r 1k sobol" main $A
ORB_KERNEL_DIR=$G/knobrev bench "r$r 1k sobol no builtin" main $A
ORB_CL_OPTIONS="-DORB_MATERIAL_KINDS=4294967295 -DORB_ROUGH_DIELECTRIC=1 -DORB_ENVIRONMENT=1" bench "r$r 1k sobol every kind" main $A
ORB_CL_OPTIONS=-DORB_SOBOL_BLOCKS=1 bench "r$r 1k sobol blocks=1" main $A
ORB_CL_OPTIONS=-DORB_SCENE_SPACE=__global bench "r$r 1k sobol global" main $A
ORB_CL_OPTIONS=-cl-nv-maxrregcount=128 bench "r$r 1k sobol cap128" main $A
ORB_CL_OPTIONS=-cl-opt-disable bench "r$r 1k sobol opt-disable" main $A
done
echo "== bounds checks, 1k sobol"
ORB_CL_OPTIONS=-DORB_BVH_CHECK=1 orb main --benchmark $A --device NVIDIA --benchmark-seconds 2 2>&1 | sort | uniq -c | sort -rn | head -20
echo "== bounds checks, 1k sobol, --spp renders"
for spp in 1 4 16; do ORB_CL_OPTIONS=-DORB_BVH_CHECK=1 orb main $A --device NVIDIA --spp $spp -o /tmp/c$spp.exr 2>&1 | sort | uniq -c | sort -rn | head -8; done
echo "== build log 1k"
ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose orb main --benchmark $A --device NVIDIA --benchmark-seconds 0.3 2>&1 | grep -iE 'registers|spill|stack frame|warning' | head -8
ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose ORB_KERNEL_DIR=$G/knobrev orb main --benchmark $A --device NVIDIA --benchmark-seconds 0.3 2>&1 | grep -iE 'registers|spill|stack frame' | head -4
