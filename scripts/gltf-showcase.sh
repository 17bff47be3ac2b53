#!/usr/bin/env bash
# Makes the showcase of docs/gltf.md and the README: a real glTF asset with
# roughness, the Khronos sample asset MetalRoughSpheresNoTextures (CC0,
# tests/data/gltf-sample-assets/), imported by orb-import, lit by a studio
# environment map made here, rendered by orb-render, and set beside the
# asset's own reference screenshot.
#
#   scripts/gltf-showcase.sh [BUILD_DIR] [OUT_DIR] [SPP]
#
# BUILD_DIR defaults to build (its bin/ holds orb-import, orb-render and
# orb-tonemap), OUT_DIR to docs/images, SPP to 256. Needs oiiotool
# (openimageio-tools).
#
# The map (1024 x 512, Orb's latitude-longitude layout: the centre column
# faces +x, +y up; docs/scene-format.md#environment) is a grey-blue sky over
# a dark floor with three bright soft boxes behind the camera (the asset's
# automatic camera looks from +z towards -z), so that smooth spheres mirror
# them sharply and rough ones blur them: roughness is what shows.
set -euo pipefail

build=${1:-build}
out=${2:-docs/images}
spp=${3:-256}
root=$(cd "$(dirname "$0")/.." && pwd)
asset=$root/tests/data/gltf-sample-assets/MetalRoughSpheresNoTextures
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

paste() {  # paste PATTERN W H X Y: a pattern of W x H pixels pasted onto the map at (X, Y)
    args+=(--pattern "$1" "$2x$3" 3 --swap --paste "+$4+$5")
}
args=(--pattern constant:color=0.06,0.055,0.05 1024x512 3)  # the floor, below the horizon
paste fill:top=0.32,0.35,0.42:bottom=0.18,0.19,0.21 1024 256 0 0  # the sky
paste constant:color=14,14,14 110 70 690 80      # soft boxes behind the camera: up, to its right
paste constant:color=9,8.5,8 70 90 860 150       # to its left, warmer
paste constant:color=5,5,5.5 40 140 560 200      # a tall strip further right
oiiotool "${args[@]}" -d float -o "$work/studio.exr"

"$build/bin/orb-import" -q "$asset/MetalRoughSpheresNoTextures.glb" --environment "$work/studio.exr" \
    -o "$work/scene.json"
"$build/bin/orb-render" "$work/scene.json" --width 512 --height 512 --spp "$spp" --seed 1 -o "$work/render.exr" -q
# Alpha is the spheres' coverage: keep the colour only, so the PNG shows the sky.
oiiotool "$work/render.exr" --ch R,G,B -o "$work/opaque.exr"
"$build/bin/orb-tonemap" -q "$work/opaque.exr" -o "$work/orb.png"
oiiotool "$asset/screenshot.png" --ch R,G,B --resize 512x512 -o "$work/reference.png"
oiiotool "$work/orb.png" "$work/reference.png" --mosaic 2x1 -o "$out/gltf-metal-rough-spheres.png"
"$build/bin/orb-tonemap" -q "$work/studio.exr" -o "$work/studio-full.png"
oiiotool "$work/studio-full.png" --resize 512x256 -o "$out/gltf-studio-map.png"

echo "wrote $out/gltf-metal-rough-spheres.png and $out/gltf-studio-map.png"
