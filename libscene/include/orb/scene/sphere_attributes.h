// Per-sphere data kept as arrays beside the shared materials, so a million
// particles coloured one by one read, hash and upload as fast as a plain
// million: one colour per sphere (instead of one material per colour) and the
// named properties a reader found (temperature, B-factor, element, chain ...)
// for --color-by and --radius-by. Index i of every array is Scene::spheres[i].
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace orb {

// The value of a sphere that has none of a property: a molecule's cell and
// lights are spheres, not atoms, and carry no B-factor or element. Written
// as null in the JSON form; styling leaves such spheres as they are.
inline constexpr float kNoValue = std::numeric_limits<float>::quiet_NaN();
inline bool has_value(float value) { return !std::isnan(value); }

// One named value per sphere. A numeric property (temperature, b_factor)
// keeps its numbers; a categorical one (element, chain, residue name, type)
// keeps each sphere's index into `labels`, so "Fe" is stored once. A sphere
// may have no value (kNoValue).
struct SphereProperty {
    std::string name;            // as the file names it ("b_factor", "element", "c_peratom")
    std::vector<float> values;   // one per sphere; categorical: the index into labels
    std::vector<std::string> labels;  // empty: numeric; else the categories
    bool categorical() const { return !labels.empty(); }
    // Equal names, labels and values, a sphere without a value (NaN) equal to another without.
    bool operator==(const SphereProperty& other) const;
};

struct SphereAttributes {
    // Empty, or three floats (linear Rec.709, each in [0,1]) per sphere that
    // replace the colour of the sphere's material (its kind, roughness,
    // emission and the rest still come from the material).
    std::vector<float> colors;
    std::vector<SphereProperty> properties;
    bool empty() const { return colors.empty() && properties.empty(); }
    bool operator==(const SphereAttributes&) const = default;
};

}  // namespace orb
