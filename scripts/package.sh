#!/usr/bin/env bash
# Builds Orb's Debian package (docs/install.md) from a clean clone of the
# committed HEAD: a fresh Release build without the test suite, with Debian's
# hardening flags (dpkg-buildflags), then `cpack -G DEB` and lintian, whose
# errors fail the script. The .deb lands in out/ (or $ORB_PACKAGE_DIR).
#   scripts/package.sh [extra cmake options, e.g. -DCMAKE_CXX_COMPILER_LAUNCHER=ccache]
# Uncommitted changes are not packaged: the package is what a clone builds.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${ORB_PACKAGE_DIR:-$root/out}
jobs=${ORB_JOBS:-$(nproc)}
"$root/scripts/install-deps.sh" --package

work=$(mktemp -d "${TMPDIR:-/tmp}/orb-package.XXXXXX")
trap 'rm -rf "$work"' EXIT
commit=$(git -C "$root" rev-parse HEAD)
[[ -z $(git -C "$root" status --porcelain --untracked-files=no) ]] ||
  echo "package: uncommitted changes in $root are left out: packaging commit ${commit:0:12}" >&2
git clone --quiet --no-local --no-checkout "$root" "$work/orb"
git -C "$work/orb" checkout --quiet --detach "$commit"

# Debian's compiler and linker flags (fortify, stack protector, RELRO, bindnow);
# CMake reads CFLAGS/CXXFLAGS/LDFLAGS, not CPPFLAGS. The Release build type's
# -O3 comes after them and wins over their -O2.
# Asked in the clone, so that -ffile-prefix-map maps its path to ".".
eval "$(cd "$work/orb" && DEB_BUILD_MAINT_OPTIONS=hardening=+all dpkg-buildflags --export=sh)"
export CFLAGS="$CPPFLAGS $CFLAGS" CXXFLAGS="$CPPFLAGS $CXXFLAGS"
cmake -S "$work/orb" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DORB_BUILD_TESTS=OFF "$@" >/dev/null
cmake --build "$work/build" -j "$jobs"
(cd "$work/build" && cpack -G DEB -B "$work/package")
deb=$(find "$work/package" -maxdepth 1 -name 'orb_*.deb')

echo "package: lintian $(basename "$deb")"
lintian --fail-on error "$deb" || { echo "package: lintian found errors" >&2; exit 1; }
mkdir -p "$out"
cp "$deb" "$out/"
echo "package: wrote $out/$(basename "$deb")"
