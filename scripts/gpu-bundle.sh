#!/usr/bin/env bash
# Packs orb-render and the shared libraries a bare GPU node lacks into one
# folder (default .gpu/), for running it where nothing can be installed.
# On the node:  export LD_LIBRARY_PATH=$PWD/.gpu:$LD_LIBRARY_PATH; .gpu/orb-render --list-devices
#
# ORB_PYTHON_BUNDLE=/path/to/python3.X adds the Python module's core, orb._orb
# (not orb._image, whose OpenImageIO does not fit), built for that interpreter
# in a build folder of its own (ORB_PYTHON_BUILD_DIR, default build-python3.X)
# into .gpu/python/orb, the libraries it links, and a numpy wheel for that
# Python (ORB_NUMPY_WHEEL, else `pip download`ed once into the build folder),
# which scripts/gpu-node-env.sh unpacks where the node has no numpy. The node
# needs the same Python minor version (Ubuntu 24.04: python3.12).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ORB_BUILD_DIR:-$root/build}
out=${1:-$root/.gpu}
mkdir -p "$out"

# Copies into $out everything `ldd $1` lists that is not part of a base system.
copy_libraries_of() {
  ldd "$1" | awk '/=> \// {print $3}' |
    grep -vE '/(libc|libm|libpthread|libdl|librt|libgcc_s|libstdc\+\+|ld-linux[^/]*)\.so' |
    while read -r lib; do cp -L "$lib" "$out/"; done
}

cp "$build/bin/orb-render" "$out/"
# The development tools too, when built with -DORB_BUILD_DEV=ON (dev/README.md): the
# ray-casting benchmark, the pass capture and its CUDA replay for Nsight Compute.
for tool in orb-trace-benchmark orb-capture-pass orb-cuda-replay; do
  if [[ -x "$build/bin/$tool" ]]; then cp "$build/bin/$tool" "$out/"; fi
done
# And the host BVH build's benchmark, to time the tree on the node's cores.
if [[ -x "$build/bin/orb-bvh-benchmark" ]]; then cp "$build/bin/orb-bvh-benchmark" "$out/"; fi
cp -L /usr/lib/x86_64-linux-gnu/libOpenCL.so.1 "$out/"
copy_libraries_of "$build/bin/orb-render"

if [[ -n ${ORB_PYTHON_BUNDLE:-} ]]; then
  python=$ORB_PYTHON_BUNDLE
  version=$("$python" -c 'import sys; print("%d.%d" % sys.version_info[:2])')
  python_build=${ORB_PYTHON_BUILD_DIR:-$root/build-python$version}
  # pybind11 from that Python's pip where it has one (Debian 12's 2.10 predates
  # pybind11's support of Python 3.12, which came with 2.11), else the system's.
  pybind11=()
  if pybind11_dir=$("$python" -m pybind11 --cmakedir 2>/dev/null); then pybind11=(-Dpybind11_DIR="$pybind11_dir"); fi
  launcher=()
  if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
  # The test build's flags (-Werror too), so that the compiler cache serves the libraries.
  cmake -S "$root" -B "$python_build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DORB_PYTHON=ON -DORB_BUILD_TESTS=OFF \
    -DORB_WERROR=ON -DPython_EXECUTABLE="$python" "${pybind11[@]}" "${launcher[@]}" >/dev/null
  cmake --build "$python_build" --target orb_python -j "${ORB_JOBS:-2}"
  module=$(ls "$python_build"/python/orb/_orb*.so)
  if ldd "$module" | grep -qiE 'OpenImageIO|OpenColorIO'; then
    echo "gpu-bundle.sh: $module links OpenImageIO or OpenColorIO; the bundle has no room for them" >&2
    exit 1
  fi
  rm -rf "$out/python"
  mkdir -p "$out/python/orb"
  cp "$module" "$python_build"/python/orb/*.py "$out/python/orb/"
  copy_libraries_of "$module"
  wheel=${ORB_NUMPY_WHEEL:-}
  if [[ -z $wheel ]]; then
    wheel=$(find "$python_build/wheels" -name 'numpy-*.whl' 2>/dev/null | head -1 || true)
  fi
  if [[ -z $wheel ]]; then
    "$python" -m pip download -q numpy --only-binary=:all: --python-version "$version" \
      --platform manylinux2014_x86_64 -d "$python_build/wheels"
    wheel=$(find "$python_build/wheels" -name 'numpy-*.whl' | head -1)
  fi
  rm -f "$out"/numpy-*.whl
  cp "$wheel" "$out/"
fi
du -sh "$out"
