// Adding the `denoised` layer to an EXR: the image's beauty (R, G, B)
// denoised, guided by its albedo (albedo.R/G/B) and normal (N.X/Y/Z) layers,
// written as denoised.R/G/B beside every channel and header attribute of the
// input, which are kept as they were (docs/orb-denoise.md). The channel
// names come from the film's channel table (film_channels.h).
#pragma once

#include <string>
#include <string_view>

#include "orb/denoise/denoiser.h"

namespace orb::denoise {

// The header attribute that says how the denoised layer was made (a string:
// Denoiser::description()).
inline constexpr const char* kDenoisedAttribute = "orb:denoised";

// The input file's bytes with the denoised layer added (replaced, when the
// file has one already), as the bytes of a new EXR: single-part, scanlines,
// the input's compression; the layer has the pixel type of R (HALF or
// FLOAT). Throws orb::InputError naming `source` for bytes that are not a
// flat single-part OpenEXR image, a missing or non-float layer, or values
// that are not finite; std::runtime_error when the denoiser fails.
std::string add_denoised_layer(std::string_view exr, const std::string& source, Denoiser& denoiser);

}  // namespace orb::denoise
