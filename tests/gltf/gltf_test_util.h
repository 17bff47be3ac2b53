// Helpers for the glTF tests: importing generated assets and finding things.
#pragma once

#include <string>

#include "orb/import/gltf.h"
#include "orb/scene/scene.h"

namespace orb::gltf_test {

std::string read_file(const std::string& path);
std::string generated(const std::string& name);  // path of a generated asset

// Options that leave out the default light (a key light sphere and a grey
// environment, for an asset without any light): the tests that count an
// asset's spheres count its own; gltf_default_light_test.cpp checks the light.
GltfImportOptions without_default_light(GltfImportOptions options = {});

// Imports a generated asset (name with extension) with its folder as base.
GltfImportResult import_generated(const std::string& name,
                                  const GltfImportOptions& options = without_default_light());

// The sphere with this name; fails the test (and throws) when missing.
const Sphere& sphere_named(const Scene& scene, const std::string& name);

bool any_warning_contains(const GltfImportResult& result, const std::string& text);

// The three containers every main asset is written in.
inline const char* const kContainers[] = {".gltf", "_embedded.gltf", ".glb"};

}  // namespace orb::gltf_test
