#!/usr/bin/env bash
# Measures how fast big scenes get in: generates random-sphere scenes with
# scripts/orb-gen.py (fixed seeds), times each step of loading them
# (orb_scene_load_bench: read, import+validate, write .orb/JSON, content hash),
# the real orb-import conversions, and optionally orb-render's first image.
#
#   scripts/bench-scene-load.sh                 1k, 100k and 1M spheres
#   ORB_BENCH_PRESETS="1m 10m" scripts/bench-scene-load.sh
#   ORB_BENCH_RENDER=1 scripts/bench-scene-load.sh   also time orb-render --spp 1 at 320x240 (with the BVH: seconds, not minutes)
#
# A measurement, not a test: timings on a shared machine are no pass/fail criterion.
# Environment: ORB_BUILD_DIR (default build/), ORB_BENCH_DIR (default a temporary folder, removed).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ORB_BUILD_DIR:-$root/build}
bin=$build/bin
presets=${ORB_BENCH_PRESETS:-1k 100k 1m}
for exe in orb-import orb-render orb_scene_load_bench; do
  [[ -x "$bin/$exe" ]] || { echo "bench: $bin/$exe not built (cmake --build $build --target $exe)" >&2; exit 1; }
done
work=${ORB_BENCH_DIR:-}
if [[ -z "$work" ]]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"

seconds() {  # seconds taken by a command, its output discarded
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null
  end=$(date +%s.%N)
  printf "%.3f" "$(echo "$end - $start" | bc)"
}

echo "machine: $(nproc) cores, $(uname -m), load $(cut -d' ' -f1-3 /proc/loadavg)"
for preset in $presets; do
  echo "== $preset spheres"
  echo "orb-gen .ply: $(seconds python3 "$root/scripts/orb-gen.py" --preset "$preset" -o "$work/r$preset.ply") s"
  echo "orb-gen .orb: $(seconds python3 "$root/scripts/orb-gen.py" --preset "$preset" -o "$work/r$preset.orb") s"
  "$bin/orb_scene_load_bench" "$work/r$preset.orb" "$work/r$preset.ply"
  echo "orb-import r$preset.ply -o c.orb   $(seconds "$bin/orb-import" "$work/r$preset.ply" -o "$work/c$preset.orb") s"
  echo "orb-import c.orb -o c.json          $(seconds "$bin/orb-import" "$work/c$preset.orb" -o "$work/c$preset.json") s"
  # Parsing JSON takes ~10x its size in memory: 10M spheres (1.4 GB of JSON) would need ~15 GB.
  if [[ "$preset" != 10m ]]; then
    echo "orb-import c.json -o c2.orb         $(seconds "$bin/orb-import" "$work/c$preset.json" -o "$work/c2$preset.orb") s"
    cmp "$work/c$preset.orb" "$work/c2$preset.orb" && echo "binary -> JSON -> binary: identical bytes"
  fi
  if [[ -n "${ORB_BENCH_RENDER:-}" ]]; then
    echo "orb-render c.orb --spp 1 --width 320 --height 240 (stats below):"
    /usr/bin/time -f "  wall %e s, max RSS %M kB" "$bin/orb-render" "$work/c$preset.orb" --spp 1 --width 320 --height 240 \
      -o "$work/c$preset.exr" --stats-json "$work/c$preset-stats.json"
    cat "$work/c$preset-stats.json"
  fi
done
