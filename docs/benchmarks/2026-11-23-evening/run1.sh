#!/usr/bin/env bash
# GPU run 1: bvh4 crash diagnosis, Cornell regression bisect, scaling. Runs in the repo root.
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
echo "== bvh4 at 1m, bounds checks on"
ORB_CL_OPTIONS=-DORB_BVH_CHECK=1 timeout 120 env LD_LIBRARY_PATH=$G/bvh4 $G/bvh4/orb-render /tmp/orb-1m.orb --device NVIDIA --width 1920 --height 1080 --spp 1 -o /tmp/x.exr 2>&1 | head -30
echo "== bvh4 at 1m, plain, 1 spp"
timeout 120 env LD_LIBRARY_PATH=$G/bvh4 $G/bvh4/orb-render /tmp/orb-1m.orb --device NVIDIA --width 1920 --height 1080 --spp 1 -o /tmp/y.exr 2>&1 | tail -5
echo "== bvh4 at 1m, global scene space"
ORB_CL_OPTIONS=-DORB_SCENE_SPACE=__global timeout 120 env LD_LIBRARY_PATH=$G/bvh4 $G/bvh4/orb-render /tmp/orb-1m.orb --device NVIDIA --width 1920 --height 1080 --spp 1 -o /tmp/z.exr 2>&1 | tail -5
echo "== registers"
for b in old main bvh4; do for sc in scenes/cornell.scn /tmp/orb-1m.orb; do
  echo "-- $b $sc"; ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose orb $b --benchmark $sc --device NVIDIA --benchmark-seconds 0.3 2>&1 | grep -iE 'registers|spill|stack frame' | head -3
done; done
echo "== cornell 640x480 samples/s"
for r in 1 2; do
  bench "r$r old (2a51ab0)" old scenes/cornell.scn
  bench "r$r main" main scenes/cornell.scn
  bench "r$r main independent" main scenes/cornell.scn --sampler independent
  ORB_CL_OPTIONS=-DRR_THRESHOLD=1.0f bench "r$r main independent RR_T=1" main scenes/cornell.scn --sampler independent
  ORB_CL_OPTIONS=-DRR_THRESHOLD=1.0f bench "r$r main sobol RR_T=1" main scenes/cornell.scn
  bench "r$r bvh4" bvh4 scenes/cornell.scn
  ORB_CL_OPTIONS=-DORB_SOBOL_BLOCKS=1 bench "r$r main sobol blocks=1" main scenes/cornell.scn
  for v in 0 1 2; do ORB_KERNEL_DIR=$G/kbrev ORB_CL_OPTIONS=-DORB_BREV=$v bench "r$r main kbrev BREV=$v" main scenes/cornell.scn; done
done
echo "== brev build logs"
for v in 1 2; do ORB_SHOW_BUILD_LOG=1 ORB_KERNEL_DIR=$G/kbrev ORB_CL_OPTIONS="-DORB_BREV=$v -cl-nv-verbose" orb main --benchmark scenes/cornell.scn --device NVIDIA --benchmark-seconds 0.3 2>&1 | grep -iE "error|registers|spill" | head -4; done
echo "== spheres at 1920x1080 samples/s"
for r in 1 2; do for p in 10 1k 100k 1m; do
  bench "r$r $p old" old /tmp/orb-$p.orb --width 1920 --height 1080
  bench "r$r $p main" main /tmp/orb-$p.orb --width 1920 --height 1080
  bench "r$r $p bvh4" bvh4 /tmp/orb-$p.orb --width 1920 --height 1080
done; done
