#!/usr/bin/env bash
# H100, 2026-11-24 (sixth session): time to equal error on the GPU, measured
# rather than derived. The Cornell box at 640x480 (the figure to beat's size),
# rendered at spp ladders by the current build with its defaults (Sobol,
# roulette threshold 0.25, caustic aiming), by the current build with the
# independent sampler, and by `old` (2a51ab0, the build of the 4.7 G
# samples/s figure: independent sampler, the old roulette); plus a
# converged reference from each build. The images come back as HALF EXRs
# and are scored on the development machine with orb-diff: linked as
# RUNGS/<name>/cornell/rung-SPP.{exr,json} for scripts/efficiency-rungs.py
# --reference (docs/performance.md, "Time to equal error on the GPU, measured").
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
W=/tmp/orb-eff
rm -rf "$W"; mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
S=scenes/cornell.scn
SIZE="--width 640 --height 480 --max-depth 6 --device NVIDIA --passes beauty --half -q"
render() { # bundle name spp seed extra...
  local b=$1 name=$2 spp=$3 seed=$4; shift 4
  LD_LIBRARY_PATH=$PWD/.gpu/$b:$LD_LIBRARY_PATH timeout 300 ".gpu/$b/orb-render" $S $SIZE --spp "$spp" --seed "$seed" \
    -o "$W/$name-$spp.exr" --stats-json "$W/$name-$spp.json" "$@" || echo "FAILED: $b $name $spp"
}
ladder() { # bundle name extra...
  local b=$1 name=$2; shift 2
  render "$b" "$name-warmup" 1 1 "$@"; rm -f "$W/$name-warmup-1.exr" "$W/$name-warmup-1.json"
  for spp in 64 128 256 512 1024 2048 4096; do render "$b" "$name" "$spp" 1 "$@"; done
}
for round in 1 2; do
  ladder b "r$round-new"
  ladder b "r$round-indep" --sampler independent
  ladder old "r$round-old"
done
render b ref-new 65536 1000003
render old ref-old 65536 1000003
for f in "$W"/*.json; do printf '%s ' "$(basename "$f" .json)"; python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(d['seconds'], d.get('samples_per_second'))" "$f"; done
(cd "$W" && tar cf /tmp/eff.tar *.exr *.json) && ls -la /tmp/eff.tar
(cd "$OUT" && split -b 15M -d /tmp/eff.tar eff.tar.) && ls -la "$OUT"
