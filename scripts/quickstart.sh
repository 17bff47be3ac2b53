#!/usr/bin/env bash
# One command from a fresh clone to a rendered Cornell box: installs what
# the build needs, builds the tools (not the test suite: scripts/test.sh
# does that), renders scenes/cornell.scn to cornell.exr (multi-pass) and
# cornell.png (display-referred sRGB). A second run finds both finished and
# renders nothing.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
bin=${ORB_BUILD_DIR:-$root/build}/bin
cd "$root"
"$bin/orb-render" scenes/cornell.scn -o cornell.exr --skip-existing
"$bin/orb-tonemap" cornell.exr -o cornell.png --skip-existing
echo "quickstart: $root/cornell.exr and $root/cornell.png are ready"
