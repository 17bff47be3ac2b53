#!/usr/bin/env bash
# One bsdf_sample call site (kB: sample_continuation at every vertex, aiming only where it may)
# against two (kA: main at run3's kB): the same binary (bundle `new`) with --kernel-dir.
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
orb() { LD_LIBRARY_PATH=$G/new "$G/new/orb-render" "$@"; }
for r in 1 2 3; do for sc in cornell caustic caustic3 cornell_large; do for k in kA kB; do
  out=$(orb --benchmark scenes/$sc.scn --kernel-dir $G/$k --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1)
  printf '%-40s %s\n' "r$r $sc $k" "$(sed -n 's/.*samples_per_second=//p' <<<"$out" | tail -1)"
done; done; done
