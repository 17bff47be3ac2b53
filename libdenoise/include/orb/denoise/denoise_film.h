// The denoised layer as a post layer of libexr's film encoder: orb-render
// --denoise writes it in the frame's one encode, from the values the file
// stores, beside the film's layers (the same layer and header attribute as
// add_denoised_layer gives an EXR already written, denoise_exr.h).
#pragma once

#include <memory>
#include <string>

#include "orb/denoise/denoiser.h"
#include "orb/exr/film_exr.h"

namespace orb::denoise {

// The post layer `denoised`, computed by `denoiser` (which must outlive the
// encode) from the stored beauty, albedo and normal, with the attribute
// orb:denoised. Its compute throws orb::InputError naming `source` when a
// layer is missing or a value not finite, std::runtime_error when the
// denoiser fails, and fills `times` (when given) with what it took.
exr::PostLayerPlanes denoised_post_layer(Denoiser& denoiser, const std::string& source,
                                         std::shared_ptr<DenoiseTimes> times = nullptr);

}  // namespace orb::denoise
