// Helpers of the molecular reader tests.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

#include "orb/import/molecular.h"

namespace orb::test {

inline std::string data_path(const std::string& name) {
    return std::string(ORB_TEST_DATA_DIR) + "/chemfiles-tests-data/" + name;
}

inline std::string read_data(const std::string& name) {
    std::ifstream in(data_path(name), std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The property named `name`; null when the scene has none.
inline const SphereProperty* property(const Scene& scene, const std::string& name) {
    for (const SphereProperty& p : scene.sphere_attributes.properties)
        if (p.name == name) return &p;
    return nullptr;
}

// The label sphere `i` has in a categorical property.
inline std::string label_of(const SphereProperty& p, std::size_t i) {
    return p.labels.at(static_cast<std::size_t>(p.values.at(i)));
}

// Spheres that are atoms: all but the two default lights (and no cell, unless asked).
inline std::size_t atom_count(const Scene& scene) { return scene.spheres.size() - 2; }

}  // namespace orb::test
