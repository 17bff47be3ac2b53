#!/usr/bin/env bash
# Packs orb-render and the shared libraries a bare GPU node lacks into one
# folder (default .gpu/), for running it where nothing can be installed.
# On the node:  export LD_LIBRARY_PATH=$PWD/.gpu:$LD_LIBRARY_PATH; .gpu/orb-render --list-devices
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ORB_BUILD_DIR:-$root/build}
out=${1:-$root/.gpu}
mkdir -p "$out"
cp "$build/bin/orb-render" "$out/"
# The development tools too, when built with -DORB_BUILD_DEV=ON (dev/README.md): the
# ray-casting benchmark, the pass capture and its CUDA replay for Nsight Compute.
for tool in orb-trace-benchmark orb-capture-pass orb-cuda-replay; do
  if [[ -x "$build/bin/$tool" ]]; then cp "$build/bin/$tool" "$out/"; fi
done
# And the host BVH build's benchmark, to time the tree on the node's cores.
if [[ -x "$build/bin/orb-bvh-benchmark" ]]; then cp "$build/bin/orb-bvh-benchmark" "$out/"; fi
cp -L /usr/lib/x86_64-linux-gnu/libOpenCL.so.1 "$out/"
# Everything orb-render links that is not part of a base system.
ldd "$build/bin/orb-render" | awk '/=> \// {print $3}' |
  grep -vE '/(libc|libm|libpthread|libdl|librt|libgcc_s|libstdc\+\+|ld-linux[^/]*)\.so' |
  while read -r lib; do cp -L "$lib" "$out/"; done
du -sh "$out"
