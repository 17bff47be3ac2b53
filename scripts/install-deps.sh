#!/usr/bin/env bash
# Installs what building Orb needs, from Debian's packages; with --tests also
# what running the test suite needs, with --package what scripts/package.sh
# needs. Idempotent and quick when everything is already there; non-interactive.
#   scripts/install-deps.sh [--tests] [--package]
set -euo pipefail

packages=(
  # toolchain
  g++ cmake make pkg-config python3 python3-venv
  # libraries Orb builds against
  libtinygltf-dev libstb-dev nlohmann-json3-dev libcli11-dev
  ocl-icd-opencl-dev opencl-c-headers opencl-clhpp-headers pocl-opencl-icd
  libopenexr-dev libdeflate-dev libopenimageio-dev libopencolorio-dev
  # OpenImageIO's CMake package (libopenimageio-dev) names its programs as
  # imported targets and stops the configure when /usr/bin/iconvert and the
  # others are missing: they are in this package.
  openimageio-tools
  # PDB and mmCIF (header-only; pegtl is its CIF parser's)
  gemmi-dev tao-pegtl-dev
  # the Python module (`pip install .`, docs/python.md): its headers and pybind11
  python3-dev pybind11-dev
)
test_packages=(
  # GoogleTest and GoogleMock (Debian 12's libgtest-dev has no GoogleMock):
  # only the test build (scripts/test.sh, -DORB_BUILD_TESTS=ON) needs them
  libgtest-dev libgmock-dev
  # schema validation, reference image tools
  python3-jsonschema opencolorio-tools
  # orb-farm on a one-node Slurm cluster started in a temporary folder
  slurm-wlm munge
  # the tutorial's video step (docs.commands runs every block of the docs)
  ffmpeg
  # the Python module's tests (python.pytest, python.notebook; -DORB_PYTHON=ON);
  # MDAnalysis for orb.from_mdanalysis and orb.frames, which the module imports only when called
  python3-pytest python3-numpy python3-nbconvert python3-ipykernel python3-mdanalysis
)
package_packages=(
  # cpack's Depends (dpkg-shlibdeps), the package's check, reading its man pages
  dpkg-dev lintian man-db
  # the bash completions' test
  bash-completion
  # the Python wheel beside the .deb (pip wheel)
  python3-pip python3-numpy
)
for argument in "$@"; do
  case $argument in
  --tests) packages+=("${test_packages[@]}" "${package_packages[@]}") ;;  # the suite checks the package too
  --package) packages+=("${package_packages[@]}") ;;
  *) echo "install-deps: unknown argument '$argument' (expected --tests or --package)" >&2; exit 2 ;;
  esac
done
if [[ "${ORB_WITH_FUZZ:-0}" == 1 ]]; then packages+=(clang libclang-rt-dev); fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

sudo=()
need_root() {
  if [[ $(id -u) != 0 ]]; then
    command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: $*" >&2; exit 1; }
    sudo=(sudo)
  fi
}

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#packages[@]} packages present"
else
  need_root "${missing[*]}"
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq
  # --force-unsafe-io: dpkg does not sync every unpacked file to disk, which
  # halves the install on a fresh machine (the build's 360 packages: 98 s
  # against 48 s); what a power cut would leave half-written apt puts right
  # on its next run.
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends -o Dpkg::Options::=--force-unsafe-io "${missing[@]}" >/dev/null
fi

# Intel Open Image Denoise 2 (orb-denoise, orb-render --denoise). Debian 12
# has no package; PyPI's pyoidn wheel carries Intel's official shared
# libraries. pip installs that one wheel (pinned by hash, without its Python
# dependencies, which Orb does not use) with --target into ORB_OIDN_PREFIX,
# where libdenoise looks for pyoidn/oidn/lib/libOpenImageDenoise.so.2; its
# default must match the CMake setting of the same name
# (docs/design/denoising-with-oidn.md). ORB_WITH_OIDN=0 skips it: the tools
# then work, and denoising fails with a message that says how to install it.
oidn_version=2.5.1.0
oidn_sha256=32ad13368f8de1ef63001942ad05b02a00cd732d1206d97f352d3a3f606d823e
oidn_prefix=${ORB_OIDN_PREFIX:-/usr/local/lib/orb/oidn}
if [[ "${ORB_WITH_OIDN:-1}" == 0 ]]; then
  echo "install-deps: ORB_WITH_OIDN=0: Intel Open Image Denoise not installed"
elif [[ -e "$oidn_prefix/pyoidn-$oidn_version.dist-info" && -e "$oidn_prefix/pyoidn/oidn/lib/libOpenImageDenoise.so.2" ]]; then
  echo "install-deps: Intel Open Image Denoise (pyoidn $oidn_version) present in $oidn_prefix"
else
  echo "install-deps: installing Intel Open Image Denoise (pyoidn $oidn_version from PyPI) into $oidn_prefix"
  parent=$(dirname "$oidn_prefix")
  { mkdir -p "$parent" 2>/dev/null && [[ -w "$parent" ]]; } || need_root "pyoidn into $oidn_prefix"
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  python3 -m venv "$work/venv"
  echo "pyoidn==$oidn_version --hash=sha256:$oidn_sha256" >"$work/requirements.txt"
  "$work/venv/bin/pip" install --quiet --disable-pip-version-check --no-deps --only-binary=:all: \
    --require-hashes -r "$work/requirements.txt" --target "$work/oidn"
  # Moved into place whole, so an interrupted install leaves no half prefix.
  "${sudo[@]}" mkdir -p "$(dirname "$oidn_prefix")"
  "${sudo[@]}" rm -rf "$oidn_prefix"
  "${sudo[@]}" mv "$work/oidn" "$oidn_prefix"
  "${sudo[@]}" chmod -R a+rX "$oidn_prefix"
fi
