#!/usr/bin/env bash
# Installs what building and testing Orb needs, from Debian's packages.
# Idempotent and quick when everything is already there; non-interactive.
set -euo pipefail

packages=(
  # toolchain
  g++ cmake make pkg-config python3 python3-venv
  # libraries Orb builds against
  libtinygltf-dev libstb-dev nlohmann-json3-dev libcli11-dev
  ocl-icd-opencl-dev opencl-c-headers opencl-clhpp-headers pocl-opencl-icd
  libopenexr-dev libdeflate-dev libopenimageio-dev libopencolorio-dev
  # PDB and mmCIF (header-only; pegtl is its CIF parser's)
  gemmi-dev tao-pegtl-dev
  # tests: GoogleTest, schema validation, reference image tools
  libgtest-dev python3-jsonschema openimageio-tools opencolorio-tools
  # tests: orb-farm on a one-node Slurm cluster started in a temporary folder
  slurm-wlm munge
  # tests: the tutorial's video step (docs.commands runs every block of the docs)
  ffmpeg
)
if [[ "${ORB_WITH_FUZZ:-0}" == 1 ]]; then packages+=(clang libclang-rt-dev); fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=()
if [[ $(id -u) != 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
