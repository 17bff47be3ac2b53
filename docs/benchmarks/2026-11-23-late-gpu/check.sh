#!/usr/bin/env bash
# GPU sanity and CPU (16-core PoCL) figures after the SIMD kernel, 2026-11-23 late.
set -u
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
cp /etc/OpenCL/vendors/pocl.icd /tmp/icd/ 2>/dev/null
export OCL_ICD_VENDORS=/tmp/icd LD_LIBRARY_PATH=$PWD/.gpu/b:${LD_LIBRARY_PATH:-}
R=.gpu/b/orb-render
$R --list-devices
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
echo "== NVIDIA, 1 k spheres with a tree, 1920x1080"
python3 scripts/orb-gen.py --preset 1k -o /tmp/b1k.orb >/dev/null
$R --benchmark /tmp/b1k.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 2>&1 | tail -3
$R /tmp/b1k.orb --device NVIDIA --width 320 --height 240 --spp 64 -o $OUT/b1k-gpu.exr --passes beauty 2>&1 | tail -1
echo "== PoCL on the 16-core CPU: render_pass against render_pass_simd"
for sc in cornell simple caustic3; do
  for L in 0 16; do
    echo "$sc lanes=$L $(ORB_SIMD_LANES=$L $R --benchmark scenes/$sc.scn --device 1 --benchmark-seconds 3 2>&1 | grep -o 'samples_per_second=.*')"
  done
done
for L in 0 16; do
  echo "1k lanes=$L $(ORB_SIMD_LANES=$L $R --benchmark /tmp/b1k.orb --device 1 --width 320 --height 240 --benchmark-seconds 3 2>&1 | grep -o 'samples_per_second=.*')"
done
$R /tmp/b1k.orb --device 1 --width 320 --height 240 --spp 64 -o $OUT/b1k-cpu.exr --passes beauty 2>&1 | tail -1
