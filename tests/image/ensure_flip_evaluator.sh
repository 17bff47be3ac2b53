#!/bin/sh
# Makes NVIDIA's reference FLIP implementation (the flip-evaluator package on
# PyPI, used only by tests) available as VENV/bin/flip. Safe to run
# concurrently: the installation is serialised with a lock file.
# Set ORB_FLIP_EVALUATOR=/path/to/flip to use an existing installation instead.
set -eu
venv="$1"
if [ -n "${ORB_FLIP_EVALUATOR:-}" ] && [ -x "$ORB_FLIP_EVALUATOR" ]; then exit 0; fi
[ -x "$venv/bin/flip" ] && exit 0
mkdir -p "$(dirname "$venv")"
exec 9>"$venv.lock"
flock 9
[ -x "$venv/bin/flip" ] && exit 0
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet --disable-pip-version-check flip-evaluator==1.7
test -x "$venv/bin/flip"
