#!/usr/bin/env bash
# Orb against Mitsuba 3.5.2 on this CPU: time to equal relMSE (a benchmark,
# not a test; scripts/compare_mitsuba.py says what it does). Installs Mitsuba
# into a virtual environment under build/ the first time; 3.9's llvm variant
# aborts with Debian 12's libLLVM, 3.5.2's works.
#
#   scripts/compare-mitsuba.sh scenes/cornell.scn
#   scripts/compare-mitsuba.sh scenes/*.scn --json mitsuba.json
# Arguments go to compare_mitsuba.py (--width, --height, --max-depth, --max-spp, --reference-spp, ...).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
venv=${ORB_MITSUBA_VENV:-$root/build/mitsuba-venv}
if [[ ! -x "$venv/bin/python" ]] || ! "$venv/bin/python" -c 'import mitsuba' 2>/dev/null; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q 'mitsuba==3.5.2' 'drjit==0.4.6'
fi
# libLLVM for Dr.Jit's llvm backend comes from Debian (installed with PoCL).
if [[ -z "${DRJIT_LIBLLVM_PATH:-}" ]]; then
  DRJIT_LIBLLVM_PATH=$(ls /usr/lib/x86_64-linux-gnu/libLLVM-*.so* /usr/lib/llvm-*/lib/libLLVM*.so* 2>/dev/null | head -n1 || true)
  [[ -n "$DRJIT_LIBLLVM_PATH" ]] && export DRJIT_LIBLLVM_PATH
fi
exec "$venv/bin/python" "$root/scripts/compare_mitsuba.py" "$@"
