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
