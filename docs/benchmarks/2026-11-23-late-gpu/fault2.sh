#!/usr/bin/env bash
set -u
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd LD_LIBRARY_PATH=$PWD/.gpu/b:${LD_LIBRARY_PATH:-}
R=.gpu/b/orb-render
python3 scripts/orb-gen.py --preset 1k -o /tmp/b1k.orb >/dev/null
python3 scripts/orb-gen.py --preset 100k -o /tmp/b100k.orb >/dev/null
for round in 1 2 3; do
  for cap in 64 72 80 96 128; do
    echo "round $round 1k cap $cap $(ORB_CL_OPTIONS=-cl-nv-maxrregcount=$cap $R --benchmark /tmp/b1k.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 1 2>&1 | grep -o 'samples_per_second=.*\|error.*')"
  done
  echo "round $round 1k 640x480 $($R --benchmark /tmp/b1k.orb --device NVIDIA --benchmark-seconds 1 2>&1 | grep -o 'samples_per_second=.*\|error.*')"
  echo "round $round 100k $($R --benchmark /tmp/b100k.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 1 2>&1 | grep -o 'samples_per_second=.*\|error.*')"
  echo "round $round 1k spp64 $($R /tmp/b1k.orb --device NVIDIA --width 1920 --height 1080 --spp 64 -o /tmp/x.exr --passes beauty 2>&1 | tail -1)"
  echo "round $round 1k no-env-code-test ORB_ENVIRONMENT=1 $(ORB_CL_OPTIONS=-DORB_ENVIRONMENT=1 $R --benchmark /tmp/b1k.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 1 2>&1 | grep -o 'samples_per_second=.*\|error.*')"
done
