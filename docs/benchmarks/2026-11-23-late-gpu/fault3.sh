#!/usr/bin/env bash
set -u
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd LD_LIBRARY_PATH=$PWD/.gpu/b:${LD_LIBRARY_PATH:-}
R=.gpu/b/orb-render
for p in 1k 100k 1m; do python3 scripts/orb-gen.py --preset $p -o /tmp/b$p.orb >/dev/null; done
for round in 1 2 3 4 5; do
  for p in 1k 100k 1m; do
    for cap in 96 112; do
      echo "round $round $p cap $cap $(ORB_CL_OPTIONS=-cl-nv-maxrregcount=$cap $R --benchmark /tmp/b$p.orb --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 1 2>&1 | grep -o 'samples_per_second=.*\|error.*')"
    done
  done
  echo "round $round cornell cap 96 $(ORB_CL_OPTIONS=-cl-nv-maxrregcount=96 $R --benchmark scenes/cornell.scn --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 1 2>&1 | grep -o 'samples_per_second=.*\|error.*')"
done
