// Converting between the film's sums and the per-pixel values stored in the
// EXR, channel by channel as the film's channel table says (its stored_as
// column: means, the variance of the mean, unit vectors with their length,
// values), and back.
#pragma once

#include <map>
#include <span>
#include <string>
#include <vector>

#include "orb/exr/passes.h"
#include "orb/film/film.h"

namespace orb::exr::detail {

struct Plane {
    std::string name;
    bool always_float = false;  // Z, id and resume helpers stay FLOAT under --half
    std::span<float> values;    // one float per pixel, row-major, top row first
};

// How many planes film_to_planes makes for `passes`.
std::size_t plane_count(const std::vector<Pass>& passes);

// The planes of `passes` (their channels plus resume helpers) in a fixed
// order, laid out one after another in `storage` (resized to fit; a buffer
// reused frame after frame costs no fresh pages); their values not yet set.
std::vector<Plane> plane_layout(const Film& film, const std::vector<Pass>& passes,
                                std::vector<float>& storage);

// Sets pixels [first, end) (row-major indices) of `planes`, as laid out for
// `passes`, from the film's sums: ranges can be filled on several threads.
void fill_planes(const Film& film, const std::vector<Pass>& passes, const std::vector<Plane>& planes,
                 std::size_t first, std::size_t end);

// Both, for every pixel.
std::vector<Plane> film_to_planes(const Film& film, const std::vector<Pass>& passes,
                                  std::vector<float>& storage);

// Recovers the sums of `passes` from planes read back (every channel of each
// pass, and its helpers, present). `film` is sized and has its sample count.
void planes_to_film(const std::map<std::string, std::vector<float>>& planes, const std::vector<Pass>& passes,
                    Film& film);

}  // namespace orb::exr::detail
