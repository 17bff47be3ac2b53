#!/usr/bin/env bash
# Writes scenes/studio.exr, the studio environment map of the README's glTF
# example (docs/gltf.md, "A real asset"): 1024 x 512 float RGB in Orb's
# latitude-longitude layout (the centre column faces +x, +y up;
# docs/scene-format.md#environment), a grey-blue sky over a dark floor with
# three bright soft boxes behind a camera that looks from +z towards -z (an
# asset's automatic camera), so that smooth spheres mirror them sharply and
# rough ones blur them: roughness is what shows. Orb's own work, made with
# oiiotool's patterns (openimageio-tools), the same pixels every run.
#
#   scripts/make-studio-map.sh [OUT.exr]      (default: scenes/studio.exr)
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/scenes/studio.exr}

paste() {  # paste PATTERN W H X Y: a pattern of W x H pixels pasted onto the map at (X, Y)
    args+=(--pattern "$1" "$2x$3" 3 --swap --paste "+$4+$5")
}
args=(--pattern constant:color=0.06,0.055,0.05 1024x512 3)  # the floor, below the horizon
paste fill:top=0.32,0.35,0.42:bottom=0.18,0.19,0.21 1024 256 0 0  # the sky
paste constant:color=14,14,14 110 70 690 80      # soft boxes behind the camera: up, to its right
paste constant:color=9,8.5,8 70 90 860 150       # to its left, warmer
paste constant:color=5,5,5.5 40 140 560 200      # a tall strip further right
oiiotool "${args[@]}" -d float --compression zip -o "$out"
