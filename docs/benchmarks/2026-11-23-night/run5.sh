#!/usr/bin/env bash
# A traversal stack sized to the scene's bound: kB = main's kernels with ORB_BVH_STACK_SIZE 36
# (the bound of the 1 M-sphere tree is 34, plus two spare entries) against kA = main's (48),
# same binary (bundle `new`) with --kernel-dir; 100 k and 1 M spheres at 1920x1080.
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
orb() { LD_LIBRARY_PATH=$G/new "$G/new/orb-render" "$@"; }
for p in 100k 1m; do python3 scripts/orb-gen.py --preset $p -o /tmp/orb-$p.orb >/dev/null; done
for r in 1 2 3; do for p in 100k 1m; do for k in kA kB; do
  out=$(orb --benchmark /tmp/orb-$p.orb --kernel-dir $G/$k --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1)
  printf '%-40s %s\n' "r$r $p $k" "$(sed -n 's/.*samples_per_second=//p' <<<"$out" | tail -1)"
done; done; done
