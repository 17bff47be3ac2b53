#!/usr/bin/env bash
# Makes the two pictures of docs/scene-format.md#environment: a labelled test
# map in Orb's latitude-longitude layout, and Orb's render of a mirror ball
# and a white ball under it (so the convention is shown by the renderer
# itself, not only drawn).
#
#   scripts/environment-figure.sh [BUILD_DIR] [OUT_DIR]
#
# BUILD_DIR defaults to build (its bin/ holds orb-render and orb-tonemap),
# OUT_DIR to docs/images. Needs oiiotool (openimageio-tools) and the DejaVu
# fonts. The map is 1024 x 512: four bands of colour centred on the four
# horizontal axes (the centre column faces +x), lighter sky above the
# horizon, darker ground below, each axis labelled where it lies.
set -euo pipefail

build=${1:-build}
out=${2:-docs/images}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

font=DejaVuSans
args=()
band() {  # band COLOUR X WIDTH: a band of the map, full height, pasted at X
    args+=(--pattern "constant:color=$1" "$3x512" 3 --swap --paste "+$2+0")
}
label() {  # label X Y TEXT: black text centred at (X, Y)
    args+=("--text:x=$1:y=$2:size=40:color=0,0,0:font=$font:xalign=center:yalign=center" "$3")
}

# Bands: -x at both edges (u 0 and 1), -z at u 0.25, +x at u 0.5, +z at u 0.75.
args=(--pattern constant:color=0,0,0 1024x512 3)
band 0.2,0.8,0.8 0 128
band 0.9,0.8,0.2 128 256
band 0.9,0.25,0.2 384 256
band 0.25,0.4,0.9 640 256
band 0.2,0.8,0.8 896 128
oiiotool "${args[@]}" -o "$work/bands.exr"
# Sky 1.0 above the horizon, ground 0.35 below, a dark horizon line.
oiiotool --pattern constant:color=1,1,1 1024x512 3 \
    --pattern constant:color=0.35,0.35,0.35 1024x256 3 --swap --paste +0+256 \
    --pattern constant:color=0.05,0.05,0.05 1024x4 3 --swap --paste +0+254 \
    -o "$work/shade.exr"
args=("$work/bands.exr" "$work/shade.exr" --mul)
label 512 230 "+x"
label 768 230 "+z"
label 256 230 "-z"
label 36 230 "-x"
label 988 230 "-x"
label 512 40 "+y (top row)"
label 512 480 "-y (bottom row)"
label 512 300 "u = 0.5"
label 768 300 "u = 0.75"
label 256 300 "u = 0.25"
oiiotool "${args[@]}" -d float -o "$work/test-map.exr"

# The scene: a mirror ball and a white diffuse ball on no floor, seen from +z
# looking towards -z, so the background is the -z band with +x to the right.
cat > "$work/scene.json" <<'EOF'
{ "format": "orb-scene", "version": 1,
  "camera": { "position": [0, 0.3, 3.6], "target": [0, 0.1, 0], "vfov_deg": 80 },
  "render": { "width": 640, "height": 360, "spp": 128, "max_depth": 6 },
  "environment": { "map": "test-map.exr", "intensity": 1, "rotation_deg": 0 },
  "materials": [
    { "name": "chrome", "type": "mirror", "color": [0.95, 0.95, 0.95] },
    { "name": "white", "type": "diffuse", "color": [0.8, 0.8, 0.8] }
  ],
  "spheres": [
    { "name": "mirror ball", "center": [-0.9, 0, 0], "radius": 0.8, "material": "chrome" },
    { "name": "white ball", "center": [0.9, 0, 0], "radius": 0.8, "material": "white" }
  ] }
EOF
"$build/bin/orb-render" "$work/scene.json" -o "$work/render.exr" --seed 1
# orb-tonemap shows what the camera sees, the sky included, opaque.
"$build/bin/orb-tonemap" "$work/render.exr" -o "$out/environment-render.png"
"$build/bin/orb-tonemap" "$work/test-map.exr" -o "$work/test-map-full.png"
oiiotool "$work/test-map-full.png" --resize 512x256 -o "$out/environment-map.png"
echo "wrote $out/environment-map.png and $out/environment-render.png"
