#!/usr/bin/env bash
# Builds the unit tests with AddressSanitizer + UndefinedBehaviorSanitizer
# (-DORB_SANITIZE=ON) into build-asan/ and runs them through CTest.
#
#   scripts/sanitize.sh                       build everything, run every test
#   scripts/sanitize.sh -R 'Scn|OrbImport'    extra arguments go to ctest
#   ORB_SANITIZE_TARGETS="scn_tests import_cli_tests" scripts/sanitize.sh -R 'Scn|OrbImport|FuzzCorpus'
#                                             build only those targets (then select their tests with -R)
# Environment: ORB_SANITIZE_BUILD_DIR, ORB_SANITIZE_TARGETS, ORB_JOBS.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${ORB_SANITIZE_BUILD_DIR:-$root/build-asan}
jobs=${ORB_JOBS:-$(nproc)}

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DORB_SANITIZE=ON -DORB_BUILD_TESTS=ON >/dev/null
if [[ -n "${ORB_SANITIZE_TARGETS:-}" ]]; then
  # shellcheck disable=SC2086 # a list of target names
  cmake --build "$build" -j "$jobs" --target ${ORB_SANITIZE_TARGETS}
else
  cmake --build "$build" -j "$jobs"
fi

# Leaks inside OpenCL drivers (ICD loader, PoCL's LLVM) are theirs, not ours;
# so is OpenImageIO 2.4's on a truncated PNG: its PNG read callback copies
# the error message (ImageInput::geterror) into a string and then longjmps
# out through libpng's png_error, past that string's destructor. (The fast
# unwinder cannot see past geterror in the uninstrumented library, so the
# suppression names it.)
suppressions="$build/lsan-suppressions.txt"
printf '%s\n' 'leak:libOpenCL.so' 'leak:libpocl.so' 'leak:libLLVM' 'leak:ImageInput::geterror' >"$suppressions"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$suppressions}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

# The opt-in fuzz test would start a second, clang build: not part of this run.
ctest --test-dir "$build" -j "$jobs" --output-on-failure --timeout 900 -E '^fuzz\.' "$@"
