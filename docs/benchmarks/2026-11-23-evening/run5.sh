#!/usr/bin/env bash
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
python3 scripts/orb-gen.py --preset 1k -o /tmp/orb-1k.orb >/dev/null
orb() { local b=$1; shift; LD_LIBRARY_PATH=$G/$b "$G/$b/orb-render" "$@"; }
ls /usr/local/cuda*/bin 2>/dev/null | head; which compute-sanitizer ncu cuda-gdb 2>/dev/null
CS=$(ls /usr/local/cuda*/bin/compute-sanitizer /opt/nvidia/*/compute-sanitizer 2>/dev/null | head -1)
CS=${CS:-$(which compute-sanitizer 2>/dev/null)}
echo "sanitizer: $CS"
if [ -n "$CS" ]; then
  for tool in memcheck initcheck; do echo "== $tool"
  LD_LIBRARY_PATH=$G/main timeout 200 $CS --tool $tool --print-limit 10 $G/main/orb-render /tmp/orb-1k.orb --width 960 --height 540 --device NVIDIA --spp 64 -o /tmp/s.exr 2>&1 | head -40
  done
fi
echo "== repeat fixed renders 1k sobol 256 spp x6, dmesg-free"
for r in 1 2 3 4 5 6; do orb main /tmp/orb-1k.orb --width 1920 --height 1080 --device NVIDIA --spp 256 -o /tmp/f.exr 2>&1 | tail -1; done
echo "== ORB_SOBOL_BLOCKS=0 x4"
for r in 1 2 3 4; do ORB_CL_OPTIONS=-DORB_SOBOL_BLOCKS=0 orb main /tmp/orb-1k.orb --width 1920 --height 1080 --device NVIDIA --spp 256 -o /tmp/f.exr 2>&1 | tail -1; done
