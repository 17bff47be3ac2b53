#!/usr/bin/env bash
# H100, 2026-11-24 (third session): the build with the speculative traversal
# (kernels/warp_vote.cl; orb-render sets -DORB_WARP_VOTE=1 for NVIDIA's
# OpenCL when the scene has a tree) against the same binary with the vote
# off (ORB_CL_OPTIONS=-DORB_WARP_VOTE=0, which comes after and wins), two
# rounds; and the same pass captured both ways, whose films must be equal.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
for p in 10 1k 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
bench() {  # label, options, scene args...
  local label=$1 options=$2; shift 2
  echo -n "$label: "
  ORB_CL_OPTIONS="$options" timeout 120 "$B/orb-render" --benchmark "$@" --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
}
for round in 1 2; do
  echo "== round $round cornell 640x480"
  bench default "" scenes/cornell.scn
  for p in 10 1k 100k 1m; do
    echo "== round $round $p 1920x1080"
    bench default "" $W/bench-$p.orb --width 1920 --height 1080
    bench vote-off "-DORB_WARP_VOTE=0" $W/bench-$p.orb --width 1920 --height 1080
  done
done
for v in default off; do
  o=""; [[ $v == off ]] && o="-DORB_WARP_VOTE=0"
  rm -rf /tmp/cap-$v
  ORB_CL_OPTIONS="$o" ORB_CAPTURE_PASS=/tmp/cap-$v timeout 120 "$B/orb-render" $W/bench-1m.orb --width 1920 --height 1080 --device NVIDIA --spp 3 -o /tmp/$v.exr 2>&1 | grep captured
  grep -o "ORB_WARP_VOTE=[0-9]" /tmp/cap-$v/launch.txt | tr '\n' ' '; echo
done
for f in /tmp/cap-default/*.bin; do n=$(basename $f); [[ $n == program.bin ]] && continue; cmp -s $f /tmp/cap-off/$n && echo "$n equal" || echo "$n DIFFERS"; done
