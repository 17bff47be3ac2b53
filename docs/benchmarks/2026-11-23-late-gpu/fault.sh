#!/usr/bin/env bash
set -u
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd LD_LIBRARY_PATH=$PWD/.gpu/b:${LD_LIBRARY_PATH:-}
R=.gpu/b/orb-render
python3 scripts/orb-gen.py --preset 1k -o /tmp/b1k.orb >/dev/null
for round in 1 2 3 4; do
  for k in kold kswap kcur; do
    echo "round $round $k $($R --benchmark /tmp/b1k.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 1 --kernel-dir .gpu/$k 2>&1 | grep -o 'samples_per_second=.*\|error.*')"
  done
  echo "round $round kcur independent $($R --benchmark /tmp/b1k.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 1 --sampler independent 2>&1 | grep -o 'samples_per_second=.*\|error.*')"
done
