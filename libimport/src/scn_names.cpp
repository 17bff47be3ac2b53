#include "scn_names.h"

#include <algorithm>

#include "orb/scene/detail/material_types.h"

namespace orb::scn {
namespace {

// A channel "counts" when it is at least half the strongest one: (0.75, .25, .25) is red.
std::string colour_word(const Vec3& c) {
    const double strongest = std::max({c[0], c[1], c[2]});
    if (strongest <= 0.0) return "black";
    const bool r = c[0] >= 0.5 * strongest, g = c[1] >= 0.5 * strongest, b = c[2] >= 0.5 * strongest;
    if (r && g && b) return strongest >= 0.5 ? "white" : "grey";
    if (r && g) return "yellow";
    if (g && b) return "cyan";
    if (r && b) return "magenta";
    if (r) return "red";
    if (g) return "green";
    return "blue";
}

}  // namespace

std::string describe_material(const Material& material) {
    const bool emits = material.emission[0] > 0.0 || material.emission[1] > 0.0 || material.emission[2] > 0.0;
    // A diffuse emitter is what a scene calls its light; its (usually black) reflectance is noise in the name.
    if (emits && material.type == MaterialType::Diffuse && material.color == Vec3{0.0, 0.0, 0.0}) return "light";
    std::string name = colour_word(material.color) + " " + detail::material_type_scn_word(material.type);
    return emits ? name + " light" : name;
}

std::string sphere_name(size_t index) { return "sphere " + std::to_string(index + 1); }

}  // namespace orb::scn
