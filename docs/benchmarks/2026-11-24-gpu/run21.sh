#!/usr/bin/env bash
# H100, 2026-11-24 (third session): where render_pass's lanes go idle.
# Nsight Compute through the CUDA replay (run20), with per-instruction
# source counters (SASS): executed warp instructions, thread instructions
# (their ratio is the active lanes per instruction) and stall samples.
# Then warp-state figures for variants of the Cornell box's program.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
NCU=/usr/local/cuda/bin/ncu
mkdir -p "$W"
[[ -e $W/bench-1m.orb ]] || python3 scripts/orb-gen.py --preset 1m -o $W/bench-1m.orb >/dev/null
capture() {  # name, orb-render arguments
  local name=$1; shift
  rm -rf /tmp/cap-$name
  ORB_CAPTURE_PASS=/tmp/cap-$name timeout 120 "$B/orb-render" "$@" --device NVIDIA --benchmark --benchmark-seconds 1 2>&1 | tail -1
  timeout 120 "$B/orb-cuda-replay" /tmp/cap-$name --repeat 20 | tail -2
}
capture cornell scenes/cornell.scn
capture m1 $W/bench-1m.orb --width 1920 --height 1080
for name in cornell m1; do
  echo "== ncu source counters, $name"
  rm -f /tmp/rep-$name.ncu-rep
  timeout 200 $NCU --kernel-name regex:render_pass --launch-skip 1 --launch-count 1 --set full --import-source no \
    -o /tmp/rep-$name "$B/orb-cuda-replay" /tmp/cap-$name --repeat 2 2>&1 | grep -E "ERR|rc" 
  timeout 100 $NCU -i /tmp/rep-$name.ncu-rep --page source --csv --print-source sass > $OUT/sass-$name.csv 2>&1
  echo "sass csv rc $? $(wc -c < $OUT/sass-$name.csv) bytes"
done
quick() {  # label, orb-render arguments (Cornell box variants)
  local label=$1; shift
  rm -rf /tmp/cap-q
  ORB_CAPTURE_PASS=/tmp/cap-q timeout 120 "$B/orb-render" scenes/cornell.scn "$@" --device NVIDIA --benchmark --benchmark-seconds 1 2>&1 | tail -1 | sed "s/^/$label: /"
  timeout 100 $NCU --kernel-name regex:render_pass --launch-skip 1 --launch-count 1 --section WarpStateStats --section LaunchStats --section Occupancy --section ComputeWorkloadAnalysis \
    "$B/orb-cuda-replay" /tmp/cap-q --repeat 2 2>&1 | grep -E "Active Threads|Predicated|Registers Per|Achieved Occ|Issue Slots|Warp Cycles Per Issued|floats equal" | sed "s/^/$label: /"
}
quick default
quick independent --sampler independent
ORB_CL_OPTIONS="-DRR_THRESHOLD=1.0f" quick old-roulette --sampler independent
quick direct --mode direct
