#!/usr/bin/env bash
# H100, 2026-11-24: the build with the centre ray cast before the sample loop
# and the register cap back at 64 for scenes with a tree: does anything
# fault, and how fast is it? Every render and benchmark at 1920x1080 unless
# named; the host's own build options.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
for p in 10 1k 100k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
bench() {  # label, scene, orb-render options...
  local label=$1 scene=$2; shift 2
  echo -n "$label: "
  timeout 120 "$B/orb-render" --benchmark $scene --device NVIDIA --benchmark-seconds 2 -q "$@" 2>&1 | tail -1
}
for round in 1 2 3 4; do
  for p in 10 1k 100k 1m; do bench "round $round $p" $W/bench-$p.orb --width 1920 --height 1080; done
done
for round in 1 2; do
  bench "round $round 1m independent" $W/bench-1m.orb --width 1920 --height 1080 --sampler independent
  bench "round $round cornell 640x480" scenes/cornell.scn
done
bench "1m direct" $W/bench-1m.orb --width 1920 --height 1080 --mode direct
for p in 1k 1m; do
  echo -n "render $p --spp 64, all passes: "
  timeout 120 "$B/orb-render" $W/bench-$p.orb --device NVIDIA --width 1920 --height 1080 --spp 64 -o /tmp/r.exr -q 2>&1 | tail -1
  echo "(exit $?)"
done
echo -n "render 1k --spp 512, all passes: "
timeout 120 "$B/orb-render" $W/bench-1k.orb --device NVIDIA --width 1920 --height 1080 --spp 512 -o /tmp/r.exr -q 2>&1 | tail -1
echo "(exit $?)"
for round in 1 2 3; do
  for p in 1k 1m; do
    echo -n "round $round $p without the environment's code: "
    ORB_CL_OPTIONS=-DORB_ENVIRONMENT=0 timeout 120 "$B/orb-render" --benchmark $W/bench-$p.orb --device NVIDIA \
      --width 1920 --height 1080 --benchmark-seconds 2 -q 2>&1 | tail -1
  done
done
