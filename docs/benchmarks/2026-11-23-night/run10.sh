#!/usr/bin/env bash
# Time-to-error ladders on the GPU with the night's final kernels and register caps (bundle new2),
# as run2 (320x240, depth 6, seed 1, a fresh render per rung), the default (aimed) program only;
# relMSE is computed afterwards on the development machine (orb-diff needs OpenImageIO).
set -u
G=$PWD/.gpu
mkdir -p /tmp/icd
echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
export OCL_ICD_VENDORS=/tmp/icd
orb() { LD_LIBRARY_PATH=$G/new2 "$G/new2/orb-render" "$@"; }
L=/tmp/ladder
for variant in final; do
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
tar -C /tmp/ladder -cf $OUT/final.tar final
du -sh $OUT/final.tar
# samples/s of the five scenes at 1920x1080 and the Cornell box at 640x480, bundle new2
for r in 1 2; do for size in "1920 1080" "640 480"; do set -- $size; for sc in cornell caustic caustic3 simple cornell_large; do
  [ "$1" = 640 ] && [ $sc != cornell ] && continue
  out=$(orb scenes/$sc.scn --benchmark --device NVIDIA --width $1 --height $2 --benchmark-seconds 2 -q 2>&1)
  printf '%-40s %s\n' "r$r $sc $1x$2" "$(sed -n 's/.*samples_per_second=//p' <<<"$out" | tail -1)"
done; done; done
