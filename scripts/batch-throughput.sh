#!/usr/bin/env bash
# How close a --frames batch runs to the device's own pace: renders FRAMES
# frames of SCENE into a scratch folder (removed afterwards) and prints the
# wall time from start to the last file on disk, the device's time (the
# frames' rendering seconds from --stats-json, summed), frames a second, and
# the share of the device's frame rate the batch reached.
#   scripts/batch-throughput.sh SCENE FRAMES [orb-render options...]
#   scripts/batch-throughput.sh scenes/bounce.gltf 1-48 --width 1920 --height 1080 --spp 64 --device nvidia
# ORB_RENDER names the orb-render to run (default: build/bin/orb-render);
# TMPDIR the folder the frames go to (a disk like the farm's, not tmpfs).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
render=${ORB_RENDER:-$root/build/bin/orb-render}
(($# >= 2)) || { echo "usage: $0 SCENE FRAMES [orb-render options...]" >&2; exit 2; }
scene=$1 frames=$2
shift 2
folder=$(mktemp -d "${TMPDIR:-/tmp}/orb-batch.XXXXXX")
trap 'rm -rf "$folder"' EXIT
start=$(date +%s.%N)
"$render" "$scene" --frames "$frames" -o "$folder/f.%04d.exr" --stats-json "$folder/stats.json" -q "$@"
end=$(date +%s.%N)
count=$(find "$folder" -name 'f.*.exr' | wc -l)
device=$(python3 -c 'import json,sys; d = json.load(open(sys.argv[1])); print(sum(f["seconds"] for f in d.get("frames", [d])))' "$folder/stats.json")
bytes=$(du -sb "$folder" | cut -f1)
awk -v wall="$(awk "BEGIN{print $end - $start}")" -v device="$device" -v n="$count" -v bytes="$bytes" 'BEGIN {
    printf "frames=%d wall_s=%.3f device_s=%.3f frames_per_s=%.1f device_frames_per_s=%.1f share=%.0f%% mb_per_frame=%.1f\n",
        n, wall, device, n / wall, n / device, 100 * device / wall, bytes / n / 1e6 }'
