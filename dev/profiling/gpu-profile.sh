#!/usr/bin/env bash
# Where render_pass's time goes on an NVIDIA GPU node: register
# use and spills from NVIDIA's compiler, a sweep of the register cap and the
# work-group shape on the Cornell box and on a million spheres, and, when
# Nsight Compute is installed, a profile of one render_pass launch.
# Usage on the node: dev/profiling/gpu-profile.sh BUNDLE_DIR OUT_DIR [SECONDS]
# (BUNDLE_DIR from scripts/gpu-bundle.sh; the figures in docs/performance.md
# come from this script's output.) It drives orb-render through the
# development knobs ORB_SHOW_BUILD_LOG, ORB_CL_OPTIONS and ORB_LOCAL_SIZE.
set -uo pipefail
bundle=$(cd "$1" && pwd)
out=$2
seconds=${3:-3}
mkdir -p "$out"
root=$(cd "$(dirname "$0")/../.." && pwd)
source "$root/scripts/gpu-node-env.sh" "$bundle"
render=$bundle/orb-render
export XDG_CACHE_HOME=$(mktemp -d)  # every variant builds its own program
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv 2>/dev/null

million=/tmp/orb-1m.orb
python3 "$root/scripts/orb-gen.py" --preset 1m -o "$million" >/dev/null || echo "orb-gen failed"

# Registers and spills as NVIDIA's compiler reports them (ptxas info lines).
for scene in "$root/scenes/cornell.scn" "$million"; do
  echo "== build log: $(basename "$scene")"
  ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose "$render" --benchmark "$scene" --device NVIDIA \
    --benchmark-seconds 0.5 2>&1 | grep -iE 'registers|spill|stack|ptxas|samples_per_second' | head -20
done

bench() {  # label, then orb-render arguments; prints one line
  local label=$1; shift
  local sps
  sps=$("$render" --benchmark "$@" --device NVIDIA --benchmark-seconds "$seconds" -q 2>&1 |
        sed -n 's/.*samples_per_second=\([0-9.e+]*\).*/\1/p' | tail -1)
  printf '%-40s %s\n' "$label" "${sps:-failed}"
}

ncu_bin=$(command -v ncu || ls /usr/local/cuda*/bin/ncu /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1)
if [[ -n "$ncu_bin" ]]; then
  echo "== Nsight Compute: $ncu_bin"
  for scene in "$root/scenes/cornell.scn" "$million"; do
    name=$(basename "$scene" | cut -d. -f1)
    timeout 100 "$ncu_bin" --target-processes all --kernel-name render_pass --launch-skip 2 --launch-count 1 \
      --set full "$render" "$scene" --device NVIDIA --spp 8 --width 1920 --height 1080 -o /dev/null -q \
      > "$out/ncu-$name.txt" 2>&1
    echo "ncu $name: exit $?, $(wc -l < "$out/ncu-$name.txt") lines"
    head -5 "$out/ncu-$name.txt"
  done
else
  echo "== Nsight Compute: not found"
fi

echo "== sweep: register cap x work-group shape (samples/s), two rounds"
for round in 1 2; do
  for cap in 64 80 96 128 255; do
    for shape in 16x8 32x4 8x8 32x2; do
      ORB_CL_OPTIONS=-cl-nv-maxrregcount=$cap ORB_LOCAL_SIZE=$shape \
        bench "r$round cornell 640x480 cap=$cap $shape" "$root/scenes/cornell.scn"
    done
  done
done
for round in 1; do
  for cap in 64 80 96 128 255; do
    for shape in 16x8 32x4 8x8; do
      ORB_CL_OPTIONS=-cl-nv-maxrregcount=$cap ORB_LOCAL_SIZE=$shape \
        bench "r$round 1m 1920x1080 cap=$cap $shape" "$million" --width 1920 --height 1080
    done
  done
done

