// The checks both ways of denoising an image make on its layers (an EXR read
// back, libdenoise/src/denoise_exr.cpp, or one being encoded,
// libdenoise/src/denoise_film.cpp), so both refuse the same inputs with the
// same words.
#pragma once

#include <array>
#include <functional>
#include <string>

#include "orb/tables/film_channels.h"

namespace orb::denoise::detail {

using Names = std::array<const char*, 3>;

// The three shown channels of a film channel's layer, and of the denoised
// layer, from the table.
Names names_of(film::Channel channel);
Names denoised_names();

// Throws orb::InputError naming `source` when the beauty, albedo or normal
// layer is missing (has(name): whether the image holds the channel).
void require_layers(const std::function<bool(const char*)>& has, const std::string& source);

// Throws orb::InputError when `value`, pixel `i` of `channel` of `layer`,
// is not finite (the filter spreads a NaN or an infinity over its whole
// neighbourhood).
void require_finite(float value, std::size_t i, int width, const std::string& channel, const char* layer,
                    const std::string& source);

}  // namespace orb::denoise::detail
