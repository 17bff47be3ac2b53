// Merging partial renders of one frame (orb-merge): films of disjoint sample
// ranges, rendered on any machines, add up to the film of their union.
#pragma once

#include <string>
#include <vector>

#include "orb/exr/film_exr.h"

namespace orb::exr {

struct MergeInput {
    std::string path;  // for messages
    ExrFilm file;
};

// Sums the films, each channel by its merge rule in the film's channel table
// (sums add, so every file counts in proportion to its samples; centre-ray
// values come from the file holding the lowest sample index), after checking
// that they are slices of the same render: FLOAT channels (not --half), the
// same size, seed, scene hash, scene time, mode, max depth and passes, and
// sample ranges that do not overlap. The result holds the union of the
// ranges, the sum of the targets and render seconds, and the devices of all
// inputs; its scene file and matrices are the first slice's. The sums add
// exactly (integers), so any grouping of merges gives the same bits; the
// result is `exact` when every input was (ExrFilm::exact). Throws
// orb::InputError naming the file and what differs.
ExrFilm merge_films(std::vector<MergeInput> inputs);

}  // namespace orb::exr
