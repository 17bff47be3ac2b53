#!/usr/bin/env bash
# One command from a fresh clone to a rendered Cornell box:
# installs dependencies, builds Orb, renders scenes/cornell.scn to
# cornell.exr (multi-pass) and cornell.png (display-referred sRGB).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
bin=${ORB_BUILD_DIR:-$root/build}/bin
cd "$root"
"$bin/orb-import" scenes/cornell.scn | "$bin/orb-render" - -o cornell.exr
"$bin/orb-tonemap" cornell.exr -o cornell.png
echo "quickstart: wrote $root/cornell.exr and $root/cornell.png"
