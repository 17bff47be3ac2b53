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
  printf '%-52s %s\n' "$label" "${sps:-failed: $(tail -c 120 <<<"$out" | tr '\n' ' ')}"; }
for p in 1k 1m; do A="/tmp/orb-$p.orb --width 1920 --height 1080"
for r in 1 2 3; do
bench "r$r $p sobol" main $A
bench "r$r $p independent" main $A --sampler independent
ORB_CL_OPTIONS="-DORB_ENVIRONMENT=1" bench "r$r $p sobol env=1" main $A
ORB_CL_OPTIONS="-DORB_MATERIAL_KINDS=4294967295" bench "r$r $p sobol kinds=all" main $A
ORB_CL_OPTIONS="-DORB_MATERIAL_KINDS=3" bench "r$r $p sobol kinds=3" main $A
ORB_CL_OPTIONS="-DORB_BVH_CHECK=1" bench "r$r $p sobol check" main $A
done; done
echo "== fixed-spp renders, 1k sobol"
for r in 1 2 3; do orb main /tmp/orb-1k.orb --width 1920 --height 1080 --device NVIDIA --spp 512 -o /tmp/f.exr 2>&1 | tail -1; done
