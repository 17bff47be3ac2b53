#!/usr/bin/env bash
# Builds Orb's libFuzzer targets with clang (-DORB_FUZZ=ON, ASan+UBSan) into
# build-fuzz/ and runs each for ORB_FUZZ_SECONDS seconds (default 60).
#
#   scripts/fuzz.sh                 all targets
#   scripts/fuzz.sh fuzz_scn        only the named target(s)
#   scripts/fuzz.sh --ctest         as the opt-in CTest test: skip (exit 77) unless ORB_FUZZ_SECONDS is set
#
# Seeds: tests/fuzz/corpus/<target>/ (the regression corpus, never written to)
# plus example scenes. New inputs go to build-fuzz/fuzz-work/<target>/corpus;
# crashes to build-fuzz/fuzz-work/<target>/artifacts/. A crash found becomes a
# regression input: copy it into tests/fuzz/corpus/<target>/ and fix the bug;
# tests/scn's corpus replay test then keeps it fixed in every build.
# Environment: ORB_FUZZ_SECONDS, ORB_FUZZ_BUILD_DIR, ORB_JOBS.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

if [[ "${1:-}" == --ctest ]]; then
  shift
  if [[ -z "${ORB_FUZZ_SECONDS:-}" ]]; then
    echo "fuzz: ORB_FUZZ_SECONDS is not set; skipping (set it to fuzz each target for that many seconds)"
    exit 77
  fi
fi

seconds=${ORB_FUZZ_SECONDS:-60}
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || (( seconds < 1 )); then
  echo "fuzz: ORB_FUZZ_SECONDS must be a whole number of seconds >= 1, got '$seconds'" >&2
  exit 2
fi
build=${ORB_FUZZ_BUILD_DIR:-$root/build-fuzz}
jobs=${ORB_JOBS:-$(nproc)}
for tool in clang clang++; do
  command -v "$tool" >/dev/null || { echo "fuzz: $tool not found (apt-get install clang)" >&2; exit 1; }
done

CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DORB_FUZZ=ON -DORB_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j "$jobs" --target orb_fuzzers

targets=("$@")
if (( ${#targets[@]} == 0 )); then
  for exe in "$build"/bin/fuzz_*; do
    if [[ -x "$exe" ]]; then targets+=("$(basename "$exe")"); fi
  done
fi

# Extra seed folders per target (read-only; libFuzzer writes only to the first folder).
seeds_for() {
  case "$1" in
    fuzz_scn) echo "$root/scenes" ;;
    fuzz_scene_json) echo "$root/tests/data/scene/valid" ;;
    fuzz_gltf) echo "$root/tests/data/gltf-validator-corpus" ;;
  esac
  return 0
}

failed=()
for target in "${targets[@]}"; do
  exe="$build/bin/$target"
  [[ -x "$exe" ]] || { echo "fuzz: no such target: $target" >&2; exit 2; }
  work="$build/fuzz-work/$target"
  mkdir -p "$work/corpus" "$work/artifacts"
  args=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1
        -artifact_prefix="$work/artifacts/")
  dict="$root/tests/fuzz/${target#fuzz_}.dict"
  if [[ -f "$dict" ]]; then args+=(-dict="$dict"); fi
  seed_dirs=("$root/tests/fuzz/corpus/$target")
  extra=$(seeds_for "$target")
  if [[ -n "$extra" && -d "$extra" ]]; then seed_dirs+=("$extra"); fi
  echo "fuzz: $target for ${seconds}s"
  if ! ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
       "$exe" "${args[@]}" "$work/corpus" "${seed_dirs[@]}" >"$work/log.txt" 2>&1; then
    failed+=("$target")
    tail -n 40 "$work/log.txt"
    echo "fuzz: $target FAILED; inputs in $work/artifacts/ -- copy them into tests/fuzz/corpus/$target/ and fix" >&2
  else
    grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|Done )" "$work/log.txt" | sed "s/^/fuzz: $target: /" || true
  fi
done

if (( ${#failed[@]} )); then
  echo "fuzz: failures in: ${failed[*]}" >&2
  exit 1
fi
echo "fuzz: all targets ran ${seconds}s without a finding"
