#!/usr/bin/env bash
# H100, 2026-11-24 (fourth session, review): the traversal's two forms taking
# their next child from one function (pop_deferred) instead of a macro and a
# copy, against the build before it (.gpu/kold: kernels/ of b23b96d).
# Speed at 10 to 1 M spheres and the Cornell box, NVIDIA's
# register report, and renders to completion looking for the -36 fault.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 10 1k 100k 1m 10m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
bench() { # label kernel-dir-or-empty args...
  local label=$1 kd=$2; shift 2
  echo -n "$label: "
  if [[ -n $kd ]]; then ORB_KERNEL_DIR=$kd timeout 120 "$B/orb-render" --benchmark "$@" --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
  else timeout 120 "$B/orb-render" --benchmark "$@" --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1; fi
}
for round in 1 2; do
  for v in old new; do
    kd=""; [[ $v == old ]] && kd=$PWD/.gpu/kold
    bench "round $round $v cornell" "$kd" scenes/cornell.scn
    for p in 10 1k 100k 1m; do bench "round $round $v $p" "$kd" $W/bench-$p.orb --width 1920 --height 1080; done
  done
done
for v in old new; do
  echo "== $v registers, 1 M"
  kd=$PWD/kernels; [[ $v == old ]] && kd=$PWD/.gpu/kold
  ORB_KERNEL_DIR=$kd ORB_SHOW_BUILD_LOG=1 ORB_CL_OPTIONS=-cl-nv-verbose timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 64 --height 64 --spp 1 -o /tmp/r.exr 2>&1 |
    grep -iE "render_pass|registers|spill|stack frame" | head -6
done
faults=0
for p in 1k 100k 1m; do
  for i in 1 2 3 4 5; do
    out=$(timeout 200 "$B/orb-render" $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --spp 64 --seed $i -o /tmp/r.exr -q 2>&1); rc=$?
    echo "$p seed $i: rc $rc $out"
    [[ $rc -ne 0 ]] && faults=$((faults + 1))
  done
done
out=$(timeout 300 "$B/orb-render" $W/bench-10m.orb --device NVIDIA --width 1920 --height 1080 --spp 16 -o /tmp/r.exr -q 2>&1); rc=$?
echo "10m: rc $rc $out"; [[ $rc -ne 0 ]] && faults=$((faults + 1))
echo "failed renders: $faults of 16"
