#!/usr/bin/env bash
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
S=2
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv
for p in 10 1k 100k 1m; do python3 scripts/orb-gen.py --preset $p -o /tmp/orb-$p.orb >/dev/null; done
orb() { local b=$1; shift; LD_LIBRARY_PATH=$G/$b "$G/$b/orb-render" "$@"; }
bench() { local label=$1 b=$2; shift 2
  local out; out=$(orb $b --benchmark "$@" --device NVIDIA --benchmark-seconds $S -q 2>&1)
  local sps; sps=$(sed -n 's/.*samples_per_second=\([0-9.e+]*\).*/\1/p' <<<"$out" | tail -1)
  printf '%-52s %s\n' "$label" "${sps:-failed: $(tail -c 60 <<<"$out" | tr '\n' ' ')}"; }
export ORB_CL_OPTIONS=-DORB_ENVIRONMENT=1
echo "== sobol, environment code built, tree scenes, 8 rounds"
for r in 1 2 3 4 5 6 7 8; do for p in 1k 100k 1m; do bench "r$r $p sobol env-code" main /tmp/orb-$p.orb --width 1920 --height 1080; done; done
for r in 1 2 3 4; do orb main /tmp/orb-1m.orb --width 1920 --height 1080 --device NVIDIA --spp 64 -o /tmp/f.exr --stats-json /tmp/m.json 2>&1 | tail -1; done
grep -o '"device_memory_bytes":[0-9]*' /tmp/m.json
echo "== cornell (env code built)"
for r in 1 2; do for size in "640 480" "1920 1080"; do set -- $size
  bench "r$r cornell $1x$2 sobol" main scenes/cornell.scn --width $1 --height $2
  bench "r$r cornell $1x$2 independent" main scenes/cornell.scn --width $1 --height $2 --sampler independent
done; done
echo "== 10 spheres 1080p (env code built)"
for r in 1 2; do bench "r$r 10 sobol" main /tmp/orb-10.orb --width 1920 --height 1080; bench "r$r 10 independent" main /tmp/orb-10.orb --width 1920 --height 1080 --sampler independent; done
echo "== cap 64 with env code"
for r in 1 2; do for p in 10 100k 1m; do ORB_CL_OPTIONS="-DORB_ENVIRONMENT=1 -cl-nv-maxrregcount=64" bench "r$r $p sobol cap64" main /tmp/orb-$p.orb --width 1920 --height 1080; done; done
