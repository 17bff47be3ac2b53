#!/usr/bin/env bash
# Register caps by scene kind (bundle new2: main with 72 for tree-less scenes of three or more
# packets, 96 for one or two, 64 with a tree) against the same binary with the old cap of 80 forced
# through ORB_CL_OPTIONS (the last -cl-nv-maxrregcount wins), the five SmallptGPU scenes and the
# generated 10-sphere scene at 1920x1080; the 10-sphere scene's own cap sweep (72, 80, 96).
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
orb() { local b=$1; shift; LD_LIBRARY_PATH=$G/$b "$G/$b/orb-render" "$@"; }
python3 scripts/orb-gen.py --preset 10 -o /tmp/orb-10.orb >/dev/null
for r in 1 2; do for sc in scenes/cornell.scn scenes/caustic.scn scenes/caustic3.scn scenes/simple.scn \
    scenes/cornell_large.scn /tmp/orb-10.orb; do for opt in "" -cl-nv-maxrregcount=80; do
  out=$(ORB_CL_OPTIONS=$opt orb new2 --benchmark $sc --device NVIDIA --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1)
  printf '%-50s %s\n' "r$r $(basename $sc) ${opt:-by kind}" "$(sed -n 's/.*samples_per_second=//p' <<<"$out" | tail -1)"
done; done; done
for cap in 72 80 96; do
  out=$(ORB_CL_OPTIONS=-cl-nv-maxrregcount=$cap orb new2 --benchmark /tmp/orb-10.orb --device NVIDIA --width 1920 \
        --height 1080 --benchmark-seconds 2 -q 2>&1)
  printf '%-50s %s\n' "orb-10 cap $cap" "$(sed -n 's/.*samples_per_second=//p' <<<"$out" | tail -1)"
done
