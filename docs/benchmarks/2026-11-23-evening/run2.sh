#!/usr/bin/env bash
# GPU run 2: main with the 4-wide BVH, specialised programs and the bit-reversal builtin, against 2a51ab0.
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
S=${S:-2}
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv
for p in 10 1k 100k 1m; do python3 scripts/orb-gen.py --preset $p -o /tmp/orb-$p.orb >/dev/null || echo "gen $p failed"; done
orb() { local b=$1; shift; LD_LIBRARY_PATH=$G/$b "$G/$b/orb-render" "$@"; }
bench() { # label bundle args...
  local label=$1 b=$2; shift 2
  local out; out=$(orb $b --benchmark "$@" --device NVIDIA --benchmark-seconds $S -q 2>&1)
  local sps; sps=$(sed -n 's/.*samples_per_second=\([0-9.e+]*\).*/\1/p' <<<"$out" | tail -1)
  printf '%-52s %s\n' "$label" "${sps:-failed: $(tail -c 300 <<<"$out" | tr '\n' ' ')}"
}
echo "== registers (main)"
for sc in scenes/cornell.scn scenes/materials.json /tmp/orb-1m.orb; do
  echo "-- $sc"; ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose orb main --benchmark $sc --device NVIDIA --benchmark-seconds 0.3 2>&1 | grep -iE 'registers|spill|stack frame' | head -3
done
echo "-- cornell with every kind built"
ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS="-cl-nv-verbose -DORB_MATERIAL_KINDS=4294967295 -DORB_ROUGH_DIELECTRIC=1 -DORB_ENVIRONMENT=1" orb main --benchmark scenes/cornell.scn --device NVIDIA --benchmark-seconds 0.3 2>&1 | grep -iE 'registers|spill|stack frame' | head -3
echo "== cornell samples/s"
for r in 1 2; do for size in "640 480" "1920 1080"; do set -- $size
  bench "r$r $1x$2 old (2a51ab0)" old scenes/cornell.scn --width $1 --height $2
  bench "r$r $1x$2 main sobol" main scenes/cornell.scn --width $1 --height $2
  bench "r$r $1x$2 main independent" main scenes/cornell.scn --width $1 --height $2 --sampler independent
  ORB_CL_OPTIONS=-DRR_THRESHOLD=1.0f bench "r$r $1x$2 main sobol RR_T=1" main scenes/cornell.scn --width $1 --height $2
  ORB_CL_OPTIONS=-DRR_THRESHOLD=1.0f bench "r$r $1x$2 main independent RR_T=1" main scenes/cornell.scn --width $1 --height $2 --sampler independent
  ORB_CL_OPTIONS="-DORB_MATERIAL_KINDS=4294967295 -DORB_ROUGH_DIELECTRIC=1 -DORB_ENVIRONMENT=1" bench "r$r $1x$2 main sobol every kind" main scenes/cornell.scn --width $1 --height $2
  ORB_CL_OPTIONS=-cl-nv-maxrregcount=64 bench "r$r $1x$2 main sobol cap64" main scenes/cornell.scn --width $1 --height $2
done; done
echo "== spheres at 1920x1080 samples/s"
for r in 1 2; do for p in 10 1k 100k 1m; do
  bench "r$r $p old" old /tmp/orb-$p.orb --width 1920 --height 1080
  bench "r$r $p main" main /tmp/orb-$p.orb --width 1920 --height 1080
  bench "r$r $p main independent" main /tmp/orb-$p.orb --width 1920 --height 1080 --sampler independent
  ORB_CL_OPTIONS=-cl-nv-maxrregcount=64 bench "r$r $p main cap64" main /tmp/orb-$p.orb --width 1920 --height 1080
done; done
echo "== other scenes 640x480 (main sobol / old)"
for sc in simple caustic caustic3 cornell_large; do
  bench "$sc old" old scenes/$sc.scn
  bench "$sc main" main scenes/$sc.scn
done
