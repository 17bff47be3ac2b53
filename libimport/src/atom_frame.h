// Private: one frame of atoms as a molecular reader hands it over, before it
// becomes a scene (atoms_scene.h): positions, elements, radii and the file's
// per-atom columns, and the simulation cell when the file has one.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "orb/import/elements.h"
#include "orb/scene/sphere_attributes.h"
#include "orb/scene/vec3.h"

namespace orb::molecular {

// A parallelepiped: the points origin + u·a + v·b + w·c for u, v, w in [0, 1].
struct Cell {
    Vec3 origin{0, 0, 0};
    Vec3 a{0, 0, 0}, b{0, 0, 0}, c{0, 0, 0};
};

struct AtomFrame {
    std::vector<Vec3> positions;
    // One per atom, or empty when the file names no element (LAMMPS types).
    std::vector<const Element*> elements;
    // One per atom when the file gives radii (a LAMMPS radius or diameter column); else empty.
    std::vector<double> radii;
    std::vector<SphereProperty> properties;  // one value per atom each
    std::optional<Cell> cell;
    std::vector<std::string> warnings;
};

// Builds a categorical property value by value: each new text becomes a label.
class CategoryColumn {
public:
    explicit CategoryColumn(std::string name) { property_.name = std::move(name); }
    void add(std::string_view label) {
        auto [found, inserted] = index_.try_emplace(std::string(label), property_.labels.size());
        if (inserted) property_.labels.emplace_back(label);
        property_.values.push_back(static_cast<float>(found->second));
    }
    void reserve(std::size_t count) { property_.values.reserve(count); }
    SphereProperty take() { return std::move(property_); }

private:
    SphereProperty property_;
    std::unordered_map<std::string, std::size_t> index_;
};

// The element an atom name or symbol in a file names ("C", "Fe", "FE", "6"
// as an atomic number); the unknown element for anything else, counted in
// `unknown` (name -> atoms) for one warning per frame.
const Element& element_of_symbol(std::string_view text, std::unordered_map<std::string, std::size_t>& unknown);

// "f.xyz: 3 atoms of unknown elements (Xx: 2, Qq: 1) are drawn grey, radius 2": empty when none.
std::string unknown_elements_warning(const std::string& source,
                                     const std::unordered_map<std::string, std::size_t>& unknown);

}  // namespace orb::molecular
