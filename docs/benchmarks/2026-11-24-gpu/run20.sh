#!/usr/bin/env bash
# H100, 2026-11-24 (third session): Nsight Compute on render_pass through a
# CUDA replay. orb-render captures one pass (ORB_CAPTURE_PASS), and
# orb-cuda-replay loads the program's PTX through CUDA's driver API with the
# same register cap, checks the film it leaves against OpenCL's bit for bit,
# and times it; then ncu profiles one replayed launch.
# The Cornell box at 640x480 and the 1 M cloud at 1920x1080.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
NCU=$(command -v ncu || echo /usr/local/cuda/bin/ncu); echo "ncu: $NCU"; "$NCU" --version | tail -1
[[ -e $W/bench-1m.orb ]] || python3 scripts/orb-gen.py --preset 1m -o $W/bench-1m.orb >/dev/null
capture() {  # name, orb-render arguments
  local name=$1; shift
  rm -rf /tmp/cap-$name
  ORB_CAPTURE_PASS=/tmp/cap-$name timeout 120 "$B/orb-render" "$@" --device NVIDIA --benchmark --benchmark-seconds 1 2>&1 | tail -2
  cat /tmp/cap-$name/launch.txt | grep -v "^arg"
  grep -c envreg /tmp/cap-$name/program.bin
  grep -m3 envreg /tmp/cap-$name/program.bin
  awk '/.entry/,/^\)/' /tmp/cap-$name/program.bin | head -30
  timeout 120 "$B/orb-cuda-replay" /tmp/cap-$name --repeat 20
  echo "replay rc $?"
}
capture cornell scenes/cornell.scn
capture m1 $W/bench-1m.orb --width 1920 --height 1080
for name in cornell m1; do
  echo "== ncu $name"
  timeout 240 "$NCU" --kernel-name regex:render_pass --launch-skip 1 --launch-count 1 --set full \
    "$B/orb-cuda-replay" /tmp/cap-$name --repeat 2 > $OUT/ncu-$name.txt 2>&1
  echo "ncu rc $?"; head -c 20000 $OUT/ncu-$name.txt | grep -E "==PROF==|==ERR|==WARN" | head
done
