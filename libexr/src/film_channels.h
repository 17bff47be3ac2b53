// Converting between the film's sums and the per-pixel values stored in the
// EXR, channel by channel as the film's channel table says (its stored_as
// column: means, the variance of the mean, unit vectors with their length,
// values), and back; and the exact sums a file may carry beside them.
#pragma once

#include <cstdint>
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
    bool exact_sum = false;     // one half of a channel's exact sums: UINT, its bits in `values`
    std::span<float> values;    // one value per pixel, row-major, top row first
};

// What the planes of a file hold: the layers `passes`, and with
// `exact_sums` every sum of their Sum channels as two UINT planes
// (exact_sum_channel_names).
struct PlaneSet {
    std::vector<Pass> passes;
    bool exact_sums = false;
};

// How many planes film_to_planes makes for `set`.
std::size_t plane_count(const PlaneSet& set);

// The planes of `set` (their channels, resume helpers and exact sums) in a
// fixed order, laid out one after another in `storage` (resized to fit; a
// buffer reused frame after frame costs no fresh pages); their values not
// yet set.
std::vector<Plane> plane_layout(const Film& film, const PlaneSet& set, std::vector<float>& storage);

// Sets pixels [first, end) (row-major indices) of `planes`, as laid out for
// `set`, from the film's sums: ranges can be filled on several threads.
void fill_planes(const Film& film, const PlaneSet& set, const std::vector<Plane>& planes, std::size_t first,
                 std::size_t end);

// Both, for every pixel.
std::vector<Plane> film_to_planes(const Film& film, const PlaneSet& set, std::vector<float>& storage);

// Planes as read back from a file.
struct ReadPlanes {
    std::map<std::string, std::vector<float>> values;          // every channel of the passes and their helpers
    std::map<std::string, std::vector<std::uint32_t>> exact;   // the exact sums' halves, when the file has them
};

// Recovers the sums of `set.passes` from planes read back (every channel of
// each pass, and its helpers, present; with set.exact_sums the exact sums
// too). `film` is sized and has its sample count. Exact sums are taken as
// they are, after checking that they give the stored values bit for bit
// (std::invalid_argument saying where they do not: an image changed after
// it was written); without them each sum is rebuilt from its stored mean,
// within a float rounding or two.
void planes_to_film(const ReadPlanes& planes, const PlaneSet& set, Film& film);

}  // namespace orb::exr::detail
