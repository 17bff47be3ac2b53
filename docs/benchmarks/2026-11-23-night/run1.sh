#!/usr/bin/env bash
# The lent GPU after the cheaper sampler and the caustic casters (56d8dfe, bundle `new`) against
# 2a51ab0 (bundle `old`, before the BSDF interface, Sobol and the roulette change).
# Bundles: scripts/gpu-bundle.sh .gpu/new; ORB_BUILD_DIR=<2a51ab0 build> scripts/gpu-bundle.sh .gpu/old.
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
S=2
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv
orb() { local b=$1; shift; LD_LIBRARY_PATH=$G/$b "$G/$b/orb-render" "$@"; }
bench() { local label=$1 b=$2; shift 2
  local out; out=$(orb $b --benchmark "$@" --device NVIDIA --benchmark-seconds $S -q 2>&1)
  local sps; sps=$(sed -n 's/.*samples_per_second=\([0-9.e+]*\).*/\1/p' <<<"$out" | tail -1)
  printf '%-60s %s\n' "$label" "${sps:-failed: $(tail -c 80 <<<"$out" | tr '\n' ' ')}"; }
echo "== registers (new)"
for sc in cornell caustic; do echo "-- $sc"; ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose orb new --benchmark scenes/$sc.scn --device NVIDIA --benchmark-seconds 0.3 2>&1 | grep -iE 'registers|spill|stack frame' | head -3; done
echo "== the five scenes, 1920x1080, samples/s"
for r in 1 2; do for sc in cornell caustic caustic3 simple cornell_large; do
  bench "r$r $sc new" new scenes/$sc.scn --width 1920 --height 1080
  ORB_CL_OPTIONS=-DORB_CASTER_SHARE=0.0f bench "r$r $sc new, no casters" new scenes/$sc.scn --width 1920 --height 1080
  bench "r$r $sc old" old scenes/$sc.scn --width 1920 --height 1080
done; done 2>&1 | sed 's/^/  /'
echo "== cornell 640x480"
for r in 1 2; do bench "r$r cornell 640x480 new" new scenes/cornell.scn --width 640 --height 480
  bench "r$r cornell 640x480 old" old scenes/cornell.scn --width 640 --height 480; done
echo "== spheres, 1920x1080"
for p in 10 1k 100k 1m; do python3 scripts/orb-gen.py --preset $p -o /tmp/orb-$p.orb >/dev/null; done
for p in 10 1k 100k 1m; do bench "$p new" new /tmp/orb-$p.orb --width 1920 --height 1080; bench "$p old" old /tmp/orb-$p.orb --width 1920 --height 1080; done
echo "== time-to-error ladders, 320x240, depth 6, seed 1 (fresh render per rung, as Mitsuba's are timed)"
for sc in cornell caustic caustic3 simple cornell_large; do
  mkdir -p $OUT/ladder/$sc
  for spp in 1 2 4 8 16 32 64 128 256 512 1024 2048; do
    orb new scenes/$sc.scn --device NVIDIA --width 320 --height 240 --max-depth 6 --seed 1 --spp $spp --passes beauty \
      --half -o $OUT/ladder/$sc/rung-$spp.exr --stats-json $OUT/ladder/$sc/rung-$spp.json -q || echo "$sc $spp failed"
  done
done
du -sh $OUT
