#!/usr/bin/env bash
# Makes the showcase of docs/gltf.md and the README: the Khronos sample asset
# MetalRoughSpheresNoTextures (CC0, tests/data/gltf-sample-assets/) imported
# under the studio map scenes/studio.exr (scripts/make-studio-map.sh),
# rendered and tonemapped by the README's own commands, set beside the
# asset's reference screenshot; and a picture of the map.
#
#   scripts/gltf-showcase.sh [BUILD_DIR] [OUT_DIR] [SPP]
#
# BUILD_DIR defaults to build (its bin/ holds orb-import, orb-render and
# orb-tonemap), OUT_DIR to docs/images, SPP to 256 (the README's). Needs
# oiiotool (openimageio-tools) for the side-by-side image.
set -euo pipefail

build=$(cd "${1:-build}" && pwd)
out=$(cd "${2:-docs/images}" && pwd)
spp=${3:-256}
root=$(cd "$(dirname "$0")/.." && pwd)
asset=tests/data/gltf-sample-assets/MetalRoughSpheresNoTextures
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export PATH="$build/bin:$PATH"

# The README's commands, as written, from the root of the clone (the output in $work).
cd "$root"
orb-import -q "$asset/MetalRoughSpheresNoTextures.glb" --environment scenes/studio.exr -o "$work/spheres.json"
orb-render -q "$work/spheres.json" --width 512 --height 512 --spp "$spp" --seed 1 -o "$work/spheres.exr"
orb-tonemap -q "$work/spheres.exr" -o "$work/spheres.png"

oiiotool "$work/spheres.png" --ch R,G,B -o "$work/orb.png"
oiiotool "$asset/screenshot.png" --ch R,G,B --resize 512x512 -o "$work/reference.png"
oiiotool "$work/orb.png" "$work/reference.png" --mosaic 2x1 -o "$out/gltf-metal-rough-spheres.png"
orb-tonemap -q scenes/studio.exr -o "$work/studio-full.png"
oiiotool "$work/studio-full.png" --resize 512x256 -o "$out/gltf-studio-map.png"

echo "wrote $out/gltf-metal-rough-spheres.png and $out/gltf-studio-map.png"
