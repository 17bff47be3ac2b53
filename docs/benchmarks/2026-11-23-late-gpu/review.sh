#!/usr/bin/env bash
set -u
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd LD_LIBRARY_PATH=$PWD/.gpu/b:${LD_LIBRARY_PATH:-}
R=.gpu/b/orb-render
for p in 10 1k 100k 1m; do python3 scripts/orb-gen.py --preset $p -o /tmp/b$p.orb >/dev/null; done
for round in 1 2 3; do
  echo "round $round cornell 640x480 $($R --benchmark scenes/cornell.scn --device NVIDIA --benchmark-seconds 2 2>&1 | grep -o 'samples_per_second=.*\|error.*')"
  for p in 10 1k 100k 1m; do
    echo "round $round $p $($R --benchmark /tmp/b$p.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 2>&1 | grep -o 'samples_per_second=.*\|error.*')"
  done
  echo "round $round 1k spp512 $($R /tmp/b1k.orb --device NVIDIA --width 1920 --height 1080 --spp 512 -o /tmp/x.exr --passes all 2>&1 | tail -1)"
done
$R scenes/materials.json --device NVIDIA --width 320 --height 240 --spp 64 -o $OUT/mat-gpu.exr --passes beauty 2>&1 | tail -1
$R scenes/materials.json --device 1 --width 320 --height 240 --spp 64 -o $OUT/mat-cpu.exr --passes beauty 2>&1 | tail -1
