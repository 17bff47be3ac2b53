#!/usr/bin/env bash
# Builds Orb's Debian package (docs/install.md) from a clone of the committed
# HEAD: a Release build without the test suite, with Debian's hardening flags
# (dpkg-buildflags), then `cpack -G DEB` and lintian, whose errors fail the
# script; then the Python module's wheel (`pip wheel`, docs/python.md). The
# .deb and the wheel land in out/ (or $ORB_PACKAGE_DIR).
#   scripts/package.sh [extra cmake options, e.g. -DCMAKE_CXX_COMPILER_LAUNCHER=ccache]
# Uncommitted changes are not packaged: the package is what a clone builds.
#
# A fresh build takes long (docs/install.md says how long): it is kept in
# $ORB_PACKAGE_DIR/.package-build and used again when it is of the same
# commit, the same flags and options, finished, and its clone unchanged;
# anything else builds afresh there. Each step says what it does and how
# long it took; the build prints make's percentage as it goes.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${ORB_PACKAGE_DIR:-$root/out}
jobs=${ORB_JOBS:-$(nproc)}
work=$out/.package-build
started=$SECONDS

step() { printf 'package: [%s] %s\n' "$(date -u -d "@$((SECONDS - started))" +%M:%S)" "$*" >&2; }

step "1/6 the packages the build needs (scripts/install-deps.sh --package)"
"$root/scripts/install-deps.sh" --package

commit=$(git -C "$root" rev-parse HEAD)
[[ -z $(git -C "$root" status --porcelain --untracked-files=no) ]] ||
  echo "package: uncommitted changes in $root are left out: packaging commit ${commit:0:12}" >&2

# Debian's compiler and linker flags (fortify, stack protector, RELRO, bindnow);
# CMake reads CFLAGS/CXXFLAGS/LDFLAGS, not CPPFLAGS. The Release build type's
# -O3 comes after them and wins over their -O2. Asked in the clone's folder,
# so that -ffile-prefix-map maps its path to ".".
mkdir -p "$work/orb"
flags=$(cd "$work/orb" && DEB_BUILD_MAINT_OPTIONS=hardening=+all dpkg-buildflags --export=sh)
# What the build is of: a build whose stamp says the same is used again.
identity=$(printf '%s\n' "commit $commit" "$flags" "cmake $*" | sha256sum | cut -c1-16)

reusable() {
  [[ -f $work/stamp && $(<"$work/stamp") == "$identity" ]] || return 1
  [[ $(git -C "$work/orb" rev-parse HEAD 2>/dev/null) == "$commit" ]] || return 1
  [[ -z $(git -C "$work/orb" status --porcelain 2>/dev/null) ]] || return 1
}

if reusable; then
  step "2/6 using the build of ${commit:0:12} in $work (same commit, flags and options; its clone unchanged)"
else
  step "2/6 cloning ${commit:0:12} into $work/orb (a fresh build: none of this commit, flags and options is kept)"
  rm -rf "$work/orb" "$work/build" "$work/stamp"
  mkdir -p "$work/orb"
  git clone --quiet --no-local --no-checkout "$root" "$work/orb"
  git -C "$work/orb" checkout --quiet --detach "$commit"
fi

eval "$flags"
export CFLAGS="$CPPFLAGS $CFLAGS" CXXFLAGS="$CPPFLAGS $CXXFLAGS"
step "3/6 configuring (Release, no tests)"
cmake -S "$work/orb" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DORB_BUILD_TESTS=OFF "$@" >/dev/null
if [[ -f $work/stamp ]]; then
  step "4/6 building: checking the kept build is up to date"
else
  step "4/6 building with $jobs jobs: about 16 minutes on 2 cores (docs/install.md); make shows its percentage"
fi
cmake --build "$work/build" -j "$jobs"
echo "$identity" >"$work/stamp"  # written once the build has finished

step "5/6 cpack -G DEB and lintian"
rm -rf "$work/package"
(cd "$work/build" && cpack -G DEB -B "$work/package" >/dev/null)
deb=$(find "$work/package" -maxdepth 1 -name 'orb_*.deb')
lintian --fail-on error "$deb" || { echo "package: lintian found errors" >&2; exit 1; }
cp "$deb" "$out/"
step "wrote $out/$(basename "$deb")"

# The wheel from the same clone, with the same flags; its build folder is
# kept beside the package's, so a second run rebuilds only what changed.
# scikit-build-core comes from PyPI (pip's build environment), pybind11 from
# Debian (install-deps.sh).
step "6/6 the Python wheel (pip wheel: the module and the libraries it links)"
rm -f "$out"/orb-*.whl
CMAKE_BUILD_PARALLEL_LEVEL=$jobs python3 -m pip wheel --quiet --no-deps --wheel-dir "$out" \
  --config-settings=build-dir="$work/wheel-build" "$work/orb"
step "wrote $(ls "$out"/orb-*.whl)"
