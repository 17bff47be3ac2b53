#include "gltf_test_util.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace orb::gltf_test {

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string generated(const std::string& name) { return std::string(ORB_GLTF_GENERATED_DIR) + "/" + name; }

GltfImportOptions without_default_light(GltfImportOptions options) {
    options.default_light = false;
    return options;
}

GltfImportResult import_generated(const std::string& name, const GltfImportOptions& options) {
    const std::string path = generated(name);
    const std::string dir = std::filesystem::path(path).parent_path().string();
    return import_gltf(read_file(path), path, dir, options);
}

const Sphere& sphere_named(const Scene& scene, const std::string& name) {
    for (const Sphere& s : scene.spheres)
        if (s.name == name) return s;
    ADD_FAILURE() << "no sphere named " << name;
    throw std::runtime_error("no sphere named " + name);
}

bool any_warning_contains(const GltfImportResult& result, const std::string& text) {
    for (const std::string& w : result.warnings)
        if (w.find(text) != std::string::npos) return true;
    return false;
}

}  // namespace orb::gltf_test
