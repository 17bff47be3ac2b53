#!/usr/bin/env bash
# Orb against Blender Cycles 4.5 on this CPU: time to relMSE 0.001 with
# denoising (a benchmark, not a test; scripts/compare_cycles.py says what it
# does). Installs Blender as a Python module (PyPI bpy 4.5, about 400 MB) into
# a virtual environment the first time: $ORB_PEERS_VENV, else build/peers-venv.
# bpy 4.5 needs Python 3.11 (Debian 12's).
#
#   scripts/compare-cycles.sh scenes/cornell.scn --rounds 3
#   scripts/compare-cycles.sh scenes/cornell.scn --json cycles.json
# Arguments go to compare_cycles.py (--width, --height, --rounds, --reference-spp, --cycles-reference-spp, ...).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
venv=${ORB_PEERS_VENV:-$root/build/peers-venv}
if [[ ! -x "$venv/bin/python" ]] || ! "$venv/bin/python" -c 'import bpy' 2>/dev/null; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q 'bpy==4.5.*' 'numpy>=1.26,<2'
fi
exec "$venv/bin/python" "$root/scripts/compare_cycles.py" "$@"
