#!/usr/bin/env bash
# Test-only Python packages from PyPI (never used by Orb itself), in a venv
# under the build folder so the system Python stays untouched.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
venv=${ORB_BUILD_DIR:-$root/build}/test-venv
if [[ ! -x "$venv/bin/python" ]]; then
  /usr/bin/python3 -m venv --system-site-packages "$venv"
fi
if ! "$venv/bin/python" -c "import flip_evaluator" 2>/dev/null; then
  "$venv/bin/python" -m pip install -q --disable-pip-version-check "flip-evaluator==1.7" numpy
fi
