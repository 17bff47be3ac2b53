#!/usr/bin/env bash
# The register cap for programs with a tree, again after the sampler and the casters: main's
# kernels (kA) with -cl-nv-maxrregcount=N through ORB_CL_OPTIONS (appended after the host's cap
# of 64), 100 k and 1 M spheres at 1920x1080.
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
orb() { LD_LIBRARY_PATH=$G/new "$G/new/orb-render" "$@"; }
for p in 100k 1m; do python3 scripts/orb-gen.py --preset $p -o /tmp/orb-$p.orb >/dev/null; done
for r in 1 2; do for p in 100k 1m; do for cap in 48 56 64 72 80; do
  out=$(ORB_CL_OPTIONS=-cl-nv-maxrregcount=$cap orb --benchmark /tmp/orb-$p.orb --kernel-dir $G/kA --device NVIDIA \
        --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1)
  printf '%-40s %s\n' "r$r $p cap $cap" "$(sed -n 's/.*samples_per_second=//p' <<<"$out" | tail -1)"
done; done; done
