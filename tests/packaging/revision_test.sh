#!/usr/bin/env bash
# tools/common/cmake/write_revision.cmake, which gives --version its revision:
#   - the source tree (a git checkout): "git <hash>" (with -dirty or not);
#   - a tree that is not a checkout of its own, even inside another
#     repository (a tarball unpacked there): unknown, not that repository's;
#   - -DORB_REVISION's fallback named for such a tree;
#   - an unchanged revision leaves the file untouched (nothing rebuilds).
#
#   revision_test.sh SOURCE_DIR SCRATCH_PARENT
# SCRATCH_PARENT is the build folder: inside the checkout for build/, as a
# tarball unpacked in a clone would be.
set -uo pipefail

source_dir=$(cd "$1" && pwd)
script=$source_dir/tools/common/cmake/write_revision.cmake
work=$(mktemp -d "$2/revision-test.XXXXXX")
trap 'rm -rf "$work"' EXIT
failures=0
problem() {
    printf 'FAIL: %s\n' "$*" >&2
    failures=$((failures + 1))
}
revision() { # SOURCE FALLBACK: the revision written for SOURCE
    cmake "-DSOURCE_DIR=$1" "-DOUTPUT=$work/revision.cpp" "-DFALLBACK=$2" -P "$script" || problem "the script failed for $1"
    sed -n 's/.*kRevision = "\(.*\)";/\1/p' "$work/revision.cpp"
}

expected=$(git -C "$source_dir" rev-parse --short=12 HEAD 2>/dev/null)
if [[ -n $expected ]]; then
    got=$(revision "$source_dir" "")
    [[ $got == "git "*"$expected"* ]] || problem "the checkout's revision is '$got', expected git ...$expected..."
fi

mkdir -p "$work/orb-0.1.0"
got=$(revision "$work/orb-0.1.0" "")
[[ $got == unknown* ]] || problem "a tree inside another repository reads '$got', expected unknown"
got=$(revision "$work/orb-0.1.0" "debian 0.1.0-1")
[[ $got == "debian 0.1.0-1" ]] || problem "the fallback reads '$got'"

touch -d '2000-01-01' "$work/revision.cpp"
revision "$work/orb-0.1.0" "debian 0.1.0-1" >/dev/null
[[ $(stat -c %Y "$work/revision.cpp") == $(date -d '2000-01-01' +%s) ]] || problem "an unchanged revision rewrote the file"

echo "revision_test: $failures failures"
((failures == 0))
