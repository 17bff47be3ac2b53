#!/usr/bin/env bash
# Time-to-error ladders on the GPU, 320x240, depth 6, seed 1: a fresh render per rung (as Mitsuba's
# rungs are timed), with and without the caustic casters; relMSE against the cached 16384-spp
# references is computed afterwards on the development machine (orb-diff needs OpenImageIO).
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
orb() { LD_LIBRARY_PATH=$G/new "$G/new/orb-render" "$@"; }
L=/tmp/ladder
for variant in casters none; do
  opts=""; [ $variant = none ] && opts="-DORB_CASTER_SHARE=0.0f"
  for sc in cornell caustic caustic3 simple cornell_large; do
    mkdir -p $L/$variant/$sc
    # warm the kernel caches first, untimed
    ORB_CL_OPTIONS="$opts" orb scenes/$sc.scn --device NVIDIA --width 320 --height 240 --max-depth 6 --seed 1 --spp 1 \
      --passes beauty -o /tmp/warm.exr -q
    for spp in 1 2 4 8 16 32 64 128 256 512 1024 2048; do
      ORB_CL_OPTIONS="$opts" orb scenes/$sc.scn --device NVIDIA --width 320 --height 240 --max-depth 6 --seed 1 \
        --spp $spp --passes beauty --half -o $L/$variant/$sc/rung-$spp.exr --stats-json $L/$variant/$sc/rung-$spp.json -q \
        || echo "$variant $sc $spp failed"
    done
  done
done
tar -C /tmp -cf $OUT/ladder.tar ladder
du -sh $OUT/ladder.tar
