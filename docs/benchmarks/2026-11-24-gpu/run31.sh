#!/usr/bin/env bash
# H100, 2026-11-24 (third session, review): after the review's rewrite of
# the capture (the build options now read from the program, the knobs read
# once) and of extend_path's drawing of numbers (same numbers, same work):
# the capture and replay still agree bit for bit and take the register cap
# from the options, and samples/s match run26 (Cornell 2.25 G, 1 M 0.816 G).
# Outcome: the capture is as before; the Cornell box ran 0.6% slower in both
# rounds (2.237-2.242 G), so the extend_path rewrite was not kept and main
# keeps the form run24 and run26 measured.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
[[ -e $W/bench-1m.orb ]] || python3 scripts/orb-gen.py --preset 1m -o $W/bench-1m.orb >/dev/null
for round in 1 2; do
  echo -n "round $round cornell: "; timeout 120 "$B/orb-render" --benchmark scenes/cornell.scn --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
  echo -n "round $round 1m: "; timeout 120 "$B/orb-render" --benchmark $W/bench-1m.orb --width 1920 --height 1080 --device NVIDIA --benchmark-seconds 1.5 -q 2>&1 | tail -1
done
for name in cornell m1; do
  scene=scenes/cornell.scn; [[ $name == m1 ]] && scene="$W/bench-1m.orb --width 1920 --height 1080"
  rm -rf /tmp/cap-$name
  ORB_CAPTURE_SKIP=8 ORB_CAPTURE_PASS=/tmp/cap-$name timeout 120 "$B/orb-render" $scene --device NVIDIA --benchmark --benchmark-seconds 1 2>&1 | grep captured
  grep -o "\-cl-nv-maxrregcount=[0-9]*\|-DORB_WARP_VOTE=[0-9]" /tmp/cap-$name/launch.txt | tr '\n' ' '; echo
  timeout 120 "$B/orb-cuda-replay" /tmp/cap-$name --repeat 20
done
