#!/usr/bin/env bash
# The GPU end to end: what a user waits for around the kernel (start-up,
# denoising, adaptive decisions, batches), each figure of docs/performance.md's
# table "The GPU end to end", measured in one run on the GPU node.
# Usage on the node: scripts/gpu-end-to-end.sh BUNDLE_DIR OUT_DIR [ROUNDS]
# BUNDLE_DIR is a folder made by scripts/gpu-bundle-oidn.sh (orb-render,
# orb-denoise and OIDN's CUDA device); with one of scripts/gpu-bundle.sh (no
# OIDN) the denoising rows are left out, and the run says so.
set -uo pipefail
bundle=$(cd "$1" && pwd)
out=$2
rounds=${3:-3}
mkdir -p "$out"
here=$(cd "$(dirname "$0")" && pwd)
source "$here/gpu-node-env.sh" "$bundle"
scenes=$here/../scenes
render=$bundle/orb-render
export ORB_RENDER=$render TMPDIR=${TMPDIR:-/tmp}
have_oidn=0
if [[ -e $bundle/lib/libOpenImageDenoise.so.2 ]]; then
  export ORB_OIDN_LIBRARY=$bundle/lib
  have_oidn=1
else
  echo "no OIDN in $bundle/lib (scripts/gpu-bundle-oidn.sh makes a bundle with it): the denoising rows are left out"
fi
hd=(--width 1920 --height 1080)
# One top-level figure of a --stats-json file ("startup_seconds"), "-" when absent.
stat() { python3 -c 'import json,sys; print(json.load(open(sys.argv[1])).get(sys.argv[2], "-"))' "$1" "$2"; }
wall() { local s e; s=$(date +%s.%N); "$@" >/dev/null 2>"$out/last.err"; local rc=$?; e=$(date +%s.%N)
         awk "BEGIN{printf \"%.3f\", $e - $s}"; ((rc == 0)) || { echo " (exit $rc: $(tail -1 "$out/last.err"))"; }; }

nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null
echo "== kernels into the cache (the first run builds them; it says so)"
"$render" "$scenes/cornell.scn" "${hd[@]}" --spp 1 --device nvidia -o "$out/warm.exr" 2>&1 | grep -i "build" || true
"$render" "$scenes/cornell.scn" "${hd[@]}" --spp 1 --device nvidia --passes beauty,albedo,normal -o "$out/warm.exr" -q
"$render" "$scenes/cornell.scn" "${hd[@]}" --spp 1 --device nvidia --noise-threshold 0.0316 -o "$out/warm.exr" -q

echo "== start-up: process start to the first pass (startup_seconds), warm cache"
for r in $(seq "$rounds"); do
  w=$(wall "$render" "$scenes/cornell.scn" "${hd[@]}" --spp 16 --device nvidia -o "$out/s.exr" --stats-json "$out/s.json")
  echo "plain: startup_seconds=$(stat "$out/s.json" startup_seconds) wall_s=$w"
  if ((have_oidn)); then
    w=$(wall "$render" "$scenes/cornell.scn" "${hd[@]}" --spp 16 --device nvidia --denoise -o "$out/d.exr" --stats-json "$out/d.json")
    echo "--denoise: startup_seconds=$(stat "$out/d.json" startup_seconds) wall_s=$w"
  fi
done

if ((have_oidn)); then
  echo "== cornell 1080p 16 spp --denoise: render + denoise"
  for r in $(seq "$rounds"); do
    "$render" "$scenes/cornell.scn" "${hd[@]}" --spp 16 --device nvidia --denoise -o "$out/d.exr" --stats-json "$out/d.json" -q
    python3 - "$out/d.json" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
r, d = s["seconds"], s.get("denoise_seconds", 0)
print(f"render_ms={1e3*r:.1f} denoise_ms={1e3*d:.1f} (setup {1e3*s.get('denoise_setup_seconds',0):.1f}, "
      f"filter {1e3*s.get('denoise_filter_seconds',0):.1f}) render+denoise_ms={1e3*(r+d):.1f}")
EOF
  done
  echo "== orb-denoise --device cuda on a 1080p EXR of beauty, albedo and normal"
  "$render" "$scenes/cornell.scn" "${hd[@]}" --spp 16 --device nvidia --passes beauty,albedo,normal -o "$out/p.exr" -q
  for r in $(seq "$rounds"); do
    echo "wall_s=$(wall "$bundle/orb-denoise" "$out/p.exr" -o "$out/dn.exr" --device cuda)"
  done
fi

echo "== adaptive: --target-error 0.001 at 1080p, uniform against --noise-threshold 0.0316"
for r in $(seq "$rounds"); do
  for extra in "" "--noise-threshold 0.0316"; do
    # shellcheck disable=SC2086
    w=$(wall "$render" "$scenes/cornell.scn" "${hd[@]}" --spp 100000 --target-error 0.001 $extra --device nvidia -o "$out/a.exr" --stats-json "$out/a.json")
    echo "${extra:-uniform}: wall_s=$w render_s=$(stat "$out/a.json" seconds) spp=$(stat "$out/a.json" spp) samples=$(stat "$out/a.json" samples)"
  done
done

echo "== batches: bounce.gltf 1080p 64 spp (start to the last file; share of the device's rate)"
for r in $(seq "$rounds"); do
  echo "24 frames plain: $("$here/batch-throughput.sh" "$scenes/bounce.gltf" 1-24 "${hd[@]}" --spp 64 --device nvidia)"
  if ((have_oidn)); then
    echo "24 frames --denoise: $("$here/batch-throughput.sh" "$scenes/bounce.gltf" 1-24 "${hd[@]}" --spp 64 --device nvidia --denoise)"
  fi
  echo "240 frames plain: $("$here/batch-throughput.sh" "$scenes/bounce.gltf" 1-240 "${hd[@]}" --spp 64 --device nvidia)"
done
rm -f "$out"/*.exr
