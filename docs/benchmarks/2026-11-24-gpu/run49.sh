#!/usr/bin/env bash
# H100, 2026-11-24 (seventh session): do SmallptGPU 1.6's kernel and Orb
# converge to the same image? run48 scored each renderer against its own
# converged render; this compares the two converged renders (65 536 spp,
# 640x480, every SmallptGPU scene): SmallptGPU's running mean (float32 RGB,
# rows top to bottom, as smallptgpu-bench.c writes it) against Orb's beauty,
# by orb-diff's relMSE, and the mean of each channel. Two Orb renders of
# different seeds give the noise floor of the comparison.
set -uo pipefail
python3 -m pip install -q --no-index --no-deps --no-compile --no-cache-dir --upgrade --target /tmp/site .whl/*.whl && export PYTHONPATH=/tmp/site || exit 1
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for scene in cornell cornell_large caustic caustic3 simple; do
  SPT_SEED=1000003 timeout 300 .gpu/spt/smallptgpu-bench .gpu/spt "scenes/$scene.scn" 640 480 65536 /tmp/spt | tail -1
  for seed in 1000003 7; do
    timeout 300 .gpu/b/orb-render "scenes/$scene.scn" --width 640 --height 480 --max-depth 6 --device NVIDIA \
      --passes beauty -q --spp 65536 --seed $seed -o /tmp/orb-$seed.exr
  done
  python3 - "$scene" <<'PY'
import sys
import numpy as np
import OpenEXR
def orb(path):
    with OpenEXR.File(path, separate_channels=True) as f:
        c = f.channels()
        return np.stack([np.asarray(c[n].pixels, dtype=np.float64) for n in "RGB"], axis=-1)
a, b = orb("/tmp/orb-1000003.exr"), orb("/tmp/orb-7.exr")
s = np.fromfile("/tmp/spt-65536.raw", dtype=np.float32).astype(np.float64).reshape(a.shape)
rel = lambda x, r: float(np.mean((x - r) ** 2 / (r * r + 0.01)))
print(f"{sys.argv[1]}: relMSE smallptgpu vs orb {rel(s, a):.4g}, orb vs orb (other seed) {rel(b, a):.4g}; "
      f"channel means smallptgpu {np.round(s.mean(axis=(0, 1)), 5)}, orb {np.round(a.mean(axis=(0, 1)), 5)}")
PY
  rm -f /tmp/spt-*.raw /tmp/orb-*.exr
done
