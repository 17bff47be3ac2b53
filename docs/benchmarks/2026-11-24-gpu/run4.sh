#!/usr/bin/env bash
# H100, 2026-11-24: narrowing the -36 fault. render_pass built with the
# register cap at 128 (no spills; faulted every time in run3) and one thing
# changed per line; a 2-second benchmark each at 1920x1080.
set -uo pipefail
source scripts/gpu-node-env.sh "$PWD/.gpu/b"
B=$PWD/.gpu/b
W=/tmp/orb-scenes
mkdir -p "$W"
for p in 10 1k 1m; do [[ -e $W/bench-$p.orb ]] || python3 scripts/orb-gen.py --preset $p -o $W/bench-$p.orb >/dev/null; done
bench() {  # label, extra CL options, scene, orb-render options...
  local label=$1 opts=$2 scene=$3; shift 3
  echo -n "$label: "
  ORB_CL_OPTIONS="$opts" timeout 120 "$B/orb-render" --benchmark $W/bench-$scene.orb --device NVIDIA --width 1920 --height 1080 \
    --benchmark-seconds 2 -q "$@" 2>&1 | tail -1
}
C=-cl-nv-maxrregcount=128
bench "1m cap128" "$C" 1m
bench "1m cap128 independent" "$C" 1m --sampler independent
bench "1m cap128 direct" "$C" 1m --mode direct
bench "1m cap128 max-depth 1" "$C" 1m --max-depth 1
bench "1m cap128 max-depth 2" "$C" 1m --max-depth 2
bench "1m cap128 beauty only" "$C" 1m --passes beauty
bench "1m cap128 bvh-check" "$C -DORB_BVH_CHECK=1" 1m
bench "1m cap128 local 32x4" "$C" 1m
ORB_LOCAL_SIZE=32x4 bench "1m cap128 ORB_LOCAL_SIZE=32x4" "$C" 1m
bench "1k cap128" "$C" 1k
bench "10 cap128 global scene" "$C -DORB_SCENE_SPACE=__global" 10
bench "10 cap64 global scene" "-cl-nv-maxrregcount=64 -DORB_SCENE_SPACE=__global" 10
bench "10 cap128" "$C" 10
echo -n "1m cap128 render --spp 64: "
ORB_CL_OPTIONS="$C" timeout 120 "$B/orb-render" $W/bench-1m.orb --device NVIDIA --width 1920 --height 1080 --spp 64 -o /tmp/x.exr -q 2>&1 | tail -1; echo "(exit $?)"
bench "1m cap96 (the host's)" "" 1m
