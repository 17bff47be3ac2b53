#!/usr/bin/env bash
# Installs what is missing, builds Orb with its tests, and runs the whole
# default test suite through CTest. Opt-in extras:
#   ORB_FUZZ_SECONDS=60  also build the libFuzzer targets and fuzz each for that long
#                        (CTest's fuzz.bounded_run test runs scripts/fuzz.sh)
#   ORB_SANITIZE=1       also build and run the unit tests under ASan+UBSan
#   ORB_WERROR=1         compiler warnings in Orb's own code are errors (CI sets it)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[[ -n "${ORB_FUZZ_SECONDS:-}" ]] && export ORB_WITH_FUZZ=1
"$root/scripts/install-deps.sh" --tests
"$root/scripts/build.sh" -DORB_BUILD_TESTS=ON -DORB_PYTHON=ON -DORB_WERROR="$([[ ${ORB_WERROR:-0} == 1 ]] && echo ON || echo OFF)"
build=${ORB_BUILD_DIR:-$root/build}
ctest --test-dir "$build" -j "${ORB_JOBS:-$(nproc)}" --output-on-failure --timeout 600
if [[ "${ORB_SANITIZE:-0}" == 1 ]]; then "$root/scripts/sanitize.sh"; fi
