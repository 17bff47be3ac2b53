# Sourced by the scripts that run on a GPU node (gpu-benchmark.sh,
# dev/profiling/gpu-profile.sh), or by hand in a shell there: puts the bundle's libraries
# (scripts/gpu-bundle.sh) on the loader's path and, where NVIDIA's OpenCL
# driver is installed without an ICD entry, registers it for this run only
# (docs/performance.md, "How to reproduce").
# Usage: source scripts/gpu-node-env.sh BUNDLE_DIR
export LD_LIBRARY_PATH=$1:${LD_LIBRARY_PATH:-}
if [[ -e /usr/local/nvidia/lib64/libnvidia-opencl.so.1 ]]; then
  mkdir -p /tmp/icd
  echo /usr/local/nvidia/lib64/libnvidia-opencl.so.1 > /tmp/icd/nvidia.icd
  cp /etc/OpenCL/vendors/pocl.icd /tmp/icd/ 2>/dev/null
  export OCL_ICD_VENDORS=/tmp/icd
fi
# A bundle with the Python module (gpu-bundle.sh, ORB_PYTHON_BUNDLE): its
# python folder on PYTHONPATH and, where the node's Python ($ORB_NODE_PYTHON,
# default python3) has no numpy, the bundle's numpy wheel unpacked into
# /tmp/orb-numpy (a wheel is a zip file; nothing is installed).
if [[ -d $1/python/orb ]]; then
  orb_bundle_python=$(cd "$1" && pwd)/python
  export PYTHONPATH=$orb_bundle_python${PYTHONPATH:+:$PYTHONPATH}
  if ! "${ORB_NODE_PYTHON:-python3}" -c 'import numpy' 2>/dev/null; then
    for wheel in "$1"/numpy-*.whl; do
      [[ -e $wheel ]] || continue
      [[ -d /tmp/orb-numpy/numpy ]] || "${ORB_NODE_PYTHON:-python3}" -m zipfile -e "$wheel" /tmp/orb-numpy
      export PYTHONPATH=$PYTHONPATH:/tmp/orb-numpy
    done
  fi
fi
