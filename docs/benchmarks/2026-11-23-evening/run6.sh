#!/usr/bin/env bash
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
S=${S:-2}
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv
for p in 10 1k 100k 1m; do python3 scripts/orb-gen.py --preset $p -o /tmp/orb-$p.orb >/dev/null || echo "gen $p failed"; done
orb() { local b=$1; shift; LD_LIBRARY_PATH=$G/$b "$G/$b/orb-render" "$@"; }
bench() { local label=$1 b=$2; shift 2
  local out; out=$(orb $b --benchmark "$@" --device NVIDIA --benchmark-seconds $S -q 2>&1)
  local sps; sps=$(sed -n 's/.*samples_per_second=\([0-9.e+]*\).*/\1/p' <<<"$out" | tail -1)
  printf '%-52s %s\n' "$label" "${sps:-failed: $(tail -c 120 <<<"$out" | tr '\n' ' ')}"; }
echo "== crash check: sobol benchmarks on tree scenes"
for r in 1 2 3 4 5; do for p in 1k 1m; do bench "r$r $p sobol" main /tmp/orb-$p.orb --width 1920 --height 1080; done; done
for r in 1 2 3; do orb main /tmp/orb-1k.orb --width 1920 --height 1080 --device NVIDIA --spp 512 -o /tmp/f.exr 2>&1 | tail -1; done
echo "== registers"
for sc in scenes/cornell.scn /tmp/orb-1m.orb; do echo "-- $sc"; ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose orb main --benchmark $sc --device NVIDIA --benchmark-seconds 0.3 2>&1 | grep -iE 'registers|spill|stack frame' | head -3; done
echo "== cornell samples/s"
for r in 1 2; do for size in "640 480" "1920 1080"; do set -- $size
  bench "r$r $1x$2 old (2a51ab0)" old scenes/cornell.scn --width $1 --height $2
  bench "r$r $1x$2 main sobol" main scenes/cornell.scn --width $1 --height $2
  bench "r$r $1x$2 main independent" main scenes/cornell.scn --width $1 --height $2 --sampler independent
  ORB_CL_OPTIONS=-DRR_THRESHOLD=1.0f bench "r$r $1x$2 main independent RR_T=1" main scenes/cornell.scn --width $1 --height $2 --sampler independent
done; done
echo "== spheres at 1920x1080 samples/s"
for r in 1 2; do for p in 10 1k 100k 1m; do
  bench "r$r $p old" old /tmp/orb-$p.orb --width 1920 --height 1080
  bench "r$r $p main" main /tmp/orb-$p.orb --width 1920 --height 1080
  bench "r$r $p main independent" main /tmp/orb-$p.orb --width 1920 --height 1080 --sampler independent
  ORB_CL_OPTIONS=-cl-nv-maxrregcount=64 bench "r$r $p main cap64" main /tmp/orb-$p.orb --width 1920 --height 1080
done; done
echo "== device memory, 1m"
orb main /tmp/orb-1m.orb --width 1920 --height 1080 --device NVIDIA --spp 4 -o /tmp/m.exr --stats-json /tmp/m.json 2>&1 | tail -1; grep -o '"device_memory_bytes":[0-9]*' /tmp/m.json
