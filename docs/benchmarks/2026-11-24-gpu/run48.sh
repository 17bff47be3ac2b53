#!/usr/bin/env bash
# H100, 2026-11-24 (seventh session): SmallptGPU 1.6's kernel beside Orb, in
# one run, by samples/s and by time to equal error. SmallptGPU runs through
# smallptgpu-bench.c (beside this script; its own host code, built on the
# development machine), with the kernel's files of tigrazone/smallptgpu1.6
# (commit 0636140; rendering_kernel.cl, camera.h, geom.h, geomfunc.h, vec.h,
# simplernd.h, not in the repository) carried in .gpu/spt. Its rungs are one
# progressive run (the kernel keeps the running mean), timed up to each rung,
# scored against its own 65 536-spp render of another seed. Orb's rungs are
# fresh renders with the defaults, as run46, scored against Orb's own
# 65 536-spp render. The five SmallptGPU scenes at 640x480, the Cornell box
# at 1920x1080. Output: RUNGS/<renderer>-<size>/<scene>/rung-SPP.{json,relmse}
# for scripts/efficiency-rungs.py.
set -uo pipefail
python3 -m pip install -q --no-index --no-deps --no-compile --no-cache-dir --upgrade --target /tmp/site .whl/*.whl && export PYTHONPATH=/tmp/site || exit 1
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
R=/tmp/rungs
rm -rf "$R"; mkdir -p "$R"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
spt() { # scene WxH last-spp
  local scene=$1 size=$2 last=$3 w=${2%x*} h=${2#*x}
  local d=$R/smallptgpu-$size/$scene
  mkdir -p "$d"
  SPT_SEED=1000003 timeout 300 .gpu/spt/smallptgpu-bench .gpu/spt "scenes/$scene.scn" "$w" "$h" 65536 /tmp/spt-ref | tail -1
  for seed in 1 2; do
    echo "-- smallptgpu $scene $size seed $seed"
    SPT_SEED=$seed timeout 300 .gpu/spt/smallptgpu-bench .gpu/spt "scenes/$scene.scn" "$w" "$h" "$last" /tmp/spt-rung \
      /tmp/spt-ref-65536.raw | tee /tmp/spt.log
    if [[ $seed == 1 ]]; then
      awk -v d="$d" -v w="$w" -v h="$h" '$1 == "spp" {
        printf "{\"width\": %d, \"height\": %d, \"seconds\": %s}\n", w, h, $4 > (d "/rung-" $2 ".json");
        printf "rung-%s %s\n", $2, $8 > (d "/rung-" $2 ".relmse") }' /tmp/spt.log
    fi
  done
  rm -f /tmp/spt-ref-*.raw /tmp/spt-rung-*.raw
}
render() { # scene WxH spp seed out-stem
  local scene=$1 size=$2 spp=$3 seed=$4 out=$5
  timeout 300 .gpu/b/orb-render "scenes/$scene.scn" --width "${size%x*}" --height "${size#*x}" --max-depth 6 \
    --device NVIDIA --passes beauty --half -q --spp "$spp" --seed "$seed" -o "$out.exr" --stats-json "$out.json" \
    || echo "FAILED: orb $scene $size $spp"
}
orb() { # scene WxH last-spp
  local scene=$1 size=$2 last=$3
  local d=$R/orb-$size/$scene
  mkdir -p "$d"
  echo "-- orb $scene $size"
  render "$scene" "$size" 65536 1000003 "$R/ref"
  render "$scene" "$size" 1 1 "$d/warm-up"; rm -f "$d"/warm-up.*
  for ((spp = 16; spp <= last; spp *= 2)); do
    render "$scene" "$size" "$spp" 1 "$d/rung-$spp"
    python3 scripts/exr-relmse.py "$R/ref.exr" "$d/rung-$spp.exr" > "$d/rung-$spp.relmse"
    rm -f "$d/rung-$spp.exr"
  done
  rm -f "$R"/ref.*
}
for scene in cornell cornell_large caustic caustic3 simple; do spt "$scene" 640x480 4096; done
spt cornell 1920x1080 2048
orb cornell 640x480 4096
orb cornell 1920x1080 2048
(cd "$R" && tar czf "$OUT/rungs.tar.gz" .) && ls -la "$OUT"
