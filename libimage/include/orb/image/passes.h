// Render passes inside a (multi-layer) image: orb-render's EXR layout (its
// layers, their names and kinds, from the film's channel table in
// libtables/include/orb/tables/film_channels.h) is
//   beauty R,G,B,A   direct.R/G/B   indirect.R/G/B   emission.R/G/B
//   albedo.R/G/B     N.X/Y/Z        Z                variance.R/G/B   id
//   background.R/G/B
// and any other "layer.channel" group counts as a pass named after its layer.
#pragma once

#include <string>
#include <vector>

#include "orb/image/image.h"
#include "orb/scene/error.h"

namespace orb::image {

// How a pass's values should be shown or compared.
enum class PassKind {
    Color,     // light or reflectance: colour-managed, FLIP applies
    Normal,    // unit vectors: shown as 0.5 + 0.5 n
    Depth,     // distances: shown normalised
    Id,        // integer labels: shown as hashed colours
    Variance,  // per-channel variance: shown as normalised standard deviation
    Data,      // anything else: compared numerically only
};

struct Pass {
    std::string name;
    PassKind kind = PassKind::Data;
    bool has_alpha = false;  // last channel of `image` is alpha (beauty only)
    Image image;             // the pass's channels only, named R,G,B[,A] / X,Y,Z / Z / id
};

// A pass the image does not have; orb-diff reports it as an error (exit 2).
struct PassMissing : InputError {
    using InputError::InputError;
};

// Canonical names accepted by --pass, in contact-sheet order.
const std::vector<std::string>& canonical_pass_names();

// Passes present in the image, canonical ones first, then other layers.
std::vector<std::string> available_passes(const Image& image);

// Extracts a pass by name ("normal" and "N", "depth" and "Z" are synonyms).
// `source` names the file in the error message. Throws PassMissing.
Pass extract_pass(const Image& image, const std::string& pass, const std::string& source);

PassKind kind_of_pass(const std::string& canonical_name);
const char* kind_name(PassKind kind);

}  // namespace orb::image
