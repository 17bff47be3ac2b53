// Synthetic films with known sums for the EXR tests, and scratch paths.
#pragma once

#include <functional>
#include <string>

#include "orb/exr/film_exr.h"
#include "orb/film/film.h"

namespace orb::exr::testing {

// A film whose sums are consistent the way the renderer's are: radiance is
// direct + indirect + emission, radiance_sq >= radiance^2 / n, |normal| <= n,
// some pixels are misses (depth +inf, id -1, no alpha).
Film synthetic_film(int width, int height, std::uint64_t spp, unsigned seed = 1);

ExrMetadata synthetic_metadata();

// A fresh path inside a per-test scratch folder.
std::string scratch_path(const std::string& name);

// The message of the orb::InputError `action` throws, or a note that it threw none.
std::string message_of(const std::function<void()>& action);

// |a - b| within a few float roundings of the larger magnitude.
bool within_float_rounding(double a, double b, double ulps = 4);

}  // namespace orb::exr::testing
