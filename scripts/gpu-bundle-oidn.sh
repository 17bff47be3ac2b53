#!/usr/bin/env bash
# Packs orb-denoise and orb-render (for --denoise), the shared libraries a
# bare GPU node lacks for them, and Intel Open Image Denoise's CUDA device
# into one folder (default
# .gpu-oidn/), for denoising where nothing can be installed (no PyPI). OIDN
# is taken from where scripts/install-deps.sh put it (ORB_OIDN_PREFIX). Its
# libraries find each other through their RPATH ($ORIGIN/../lib), so they go
# into OUT/lib. About 65 MB, nearly all of it OIDN's trained weights;
# ORB_BUNDLE_OIDN_CPU=1 adds the CPU device and TBB (5 MB more).
# On the node:
#   export LD_LIBRARY_PATH=$PWD/.gpu-oidn:$LD_LIBRARY_PATH ORB_OIDN_LIBRARY=$PWD/.gpu-oidn/lib
#   .gpu-oidn/orb-denoise IN.exr -o OUT.exr --device cuda
#   scripts/gpu-end-to-end.sh .gpu-oidn out/    # docs/performance.md, "The GPU end to end"
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ORB_BUILD_DIR:-$root/build}
out=${1:-$root/.gpu-oidn}
oidn=${ORB_OIDN_PREFIX:-/usr/local/lib/orb/oidn}/pyoidn/oidn/lib
[[ -e $oidn/libOpenImageDenoise.so.2 ]] || { echo "gpu-bundle-oidn: no OIDN in $oidn: run scripts/install-deps.sh" >&2; exit 1; }
mkdir -p "$out/lib"
cp "$build/bin/orb-denoise" "$build/bin/orb-render" "$out/"
cp -L /usr/lib/x86_64-linux-gnu/libOpenCL.so.1 "$out/"
# Everything the two link that is not part of a base system.
ldd "$build/bin/orb-denoise" "$build/bin/orb-render" | awk '/=> \// {print $3}' | sort -u |
  grep -vE '/(libc|libm|libpthread|libdl|librt|libgcc_s|libstdc\+\+|ld-linux[^/]*)\.so' |
  while read -r lib; do cp -L "$lib" "$out/"; done
libs=(libOpenImageDenoise.so.2 libOpenImageDenoise_core.so.2.5.1 libOpenImageDenoise_device_cuda.so.2.5.1)
[[ ${ORB_BUNDLE_OIDN_CPU:-0} == 1 ]] && libs+=(libOpenImageDenoise_device_cpu.so.2.5.1 libtbb.so.12)
for lib in "${libs[@]}"; do cp -L "$oidn/$lib" "$out/lib/"; done
du -sh "$out"
