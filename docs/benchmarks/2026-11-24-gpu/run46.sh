#!/usr/bin/env bash
# H100, 2026-11-24 (sixth session): time to equal error on the GPU for all
# five SmallptGPU scenes at 640x480 and the Cornell box at 1920x1080, as
# run45 measured the Cornell box at 640x480: the current build's defaults,
# the current build with the independent sampler, and `old` (2a51ab0, the
# 4.7 G build), a fresh render per rung. The node scores each rung itself
# against a converged render of the current build (scripts/exr-relmse.py,
# orb-diff's relMSE; OpenEXR's Python module carried as a wheel) and sends
# back the figures: RUNGS/<config>-<size>/<scene>/rung-SPP.{json,relmse},
# read by scripts/efficiency-rungs.py.
set -uo pipefail
python3 -m pip install -q --no-index --no-deps --no-compile --no-cache-dir --upgrade --target /tmp/site .whl/*.whl && export PYTHONPATH=/tmp/site || exit 1
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
R=/tmp/rungs
rm -rf "$R"; mkdir -p "$R"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
render() { # bundle scene WxH spp seed out-stem extra...
  local b=$1 scene=$2 size=$3 spp=$4 seed=$5 out=$6; shift 6
  LD_LIBRARY_PATH=$PWD/.gpu/$b:$LD_LIBRARY_PATH timeout 300 ".gpu/$b/orb-render" "scenes/$scene.scn" \
    --width "${size%x*}" --height "${size#*x}" --max-depth 6 --device NVIDIA --passes beauty --half -q \
    --spp "$spp" --seed "$seed" -o "$out.exr" --stats-json "$out.json" "$@" || echo "FAILED: $b $scene $size $spp"
}
ladder() { # bundle config scene WxH last-spp extra...
  local b=$1 config=$2 scene=$3 size=$4 last=$5; shift 5
  local d=$R/$config-$size/$scene
  mkdir -p "$d"
  render "$b" "$scene" "$size" 1 1 "$d/warm-up" "$@"; rm -f "$d"/warm-up.*
  for ((spp = 16; spp <= last; spp *= 2)); do
    render "$b" "$scene" "$size" "$spp" 1 "$d/rung-$spp" "$@"
    python3 scripts/exr-relmse.py "$R/ref-$size-$scene.exr" "$d/rung-$spp.exr" > "$d/rung-$spp.relmse"
    rm -f "$d/rung-$spp.exr"
  done
}
run_scene() { # scene WxH last-spp
  local scene=$1 size=$2 last=$3
  echo "== $scene $size"
  render b "$scene" "$size" 65536 1000003 "$R/ref-$size-$scene"
  render old "$scene" "$size" 65536 1000003 "$R/ref-old-$size-$scene"
  python3 scripts/exr-relmse.py "$R/ref-$size-$scene.exr" "$R/ref-old-$size-$scene.exr"
  ladder b new "$scene" "$size" "$last"
  ladder b indep "$scene" "$size" "$last" --sampler independent
  ladder old old "$scene" "$size" "$last"
  rm -f "$R"/ref-*"$scene".exr
}
for scene in cornell cornell_large caustic caustic3 simple; do run_scene "$scene" 640x480 4096; done
run_scene cornell 1920x1080 2048
(cd "$R" && tar czf "$OUT/rungs.tar.gz" .) && ls -la "$OUT"
