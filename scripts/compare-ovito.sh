#!/usr/bin/env bash
# Orb against OVITO 3.17 on a million random atoms (a benchmark, not a test;
# scripts/compare_ovito.py says what it does). Installs OVITO's Python module
# (PyPI ovito 3.17) and Pillow into a virtual environment the first time:
# $ORB_OVITO_VENV, else build/ovito-venv. OVITO renders through Vulkan even
# with Tachyon: without a GPU it needs Mesa's software driver (Debian:
# apt-get install mesa-vulkan-drivers).
#
#   scripts/compare-ovito.sh --rounds 3 --picture docs/images/ovito-vs-orb-1m-atoms.png
# Arguments go to compare_ovito.py (--atoms-count, --width, --height, --reference-spp, --keep DIR, ...).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
venv=${ORB_OVITO_VENV:-$root/build/ovito-venv}
if [[ ! -x "$venv/bin/python" ]] || ! "$venv/bin/python" -c 'import ovito, PIL' 2>/dev/null; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q 'ovito==3.17.*' pillow
fi
exec "$venv/bin/python" "$root/scripts/compare_ovito.py" "$@"
