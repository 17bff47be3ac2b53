// What a display image shows where the spheres do not cover a pixel: the
// camera's whole view, opaque (the default); the spheres alone with their
// coverage as alpha; or the spheres over a background colour.
//
// orb-render's beauty RGB is what the camera sees, the environment included,
// while A is the spheres' coverage; the environment a camera ray saw where it
// hit nothing is the `background` layer, so the spheres' own colour,
// premultiplied by A, is RGB - background (docs/design/background-and-alpha.md).
#pragma once

#include <array>
#include <string>

#include "orb/image/load.h"
#include "orb/image/passes.h"

namespace orb::image {

enum class AlphaMode {
    Opaque,       // RGB as it is, alpha dropped: what the camera sees
    Transparent,  // the spheres' colour with their coverage as alpha
    OverColor,    // the spheres over `background`, opaque
};

struct AlphaOutput {
    AlphaMode mode = AlphaMode::Opaque;
    std::array<float, 3> background{};  // OverColor: scene-linear, in the input's colour space

    bool operator==(const AlphaOutput&) const = default;
};

// A colour as --background takes it: "R,G,B" (three finite numbers >= 0,
// scene-linear) or "#rrggbb" (sRGB-encoded, decoded with the sRGB transfer
// function of IEC 61966-2-1 to linear values). Throws orb::InputError
// naming what was expected.
std::array<float, 3> parse_background_color(const std::string& text);

// The mode as the display record and messages name it: "opaque",
// "transparent" or "over R,G,B" (the linear numbers, shortest exact text).
std::string alpha_output_text(const AlphaOutput& output);

// The colour pass `pass` (of `loaded`) made ready for the view:
//   Opaque:      RGB (alpha dropped);
//   Transparent: F, A with F the spheres' colour premultiplied by A
//                (associated alpha, as EXR stores it);
//   OverColor:   F + (1 - A) * background, opaque.
// F is RGB - background layer (clamped at 0) for an orb-render EXR holding
// that layer, RGB for any other file with alpha (premultiplied, as the EXR
// convention says). An orb-render EXR without the layer whose A is below 1
// somewhere cannot give F (its RGB there holds an unknown amount of
// environment): orb::InputError telling how to render it. A pass without
// alpha comes back as it is.
Pass prepare_alpha(const Pass& pass, const LoadedImage& loaded, const AlphaOutput& output);

}  // namespace orb::image
