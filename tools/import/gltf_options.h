// orb-import's glTF options (owned by the glTF import work).
#pragma once

#include <CLI/CLI.hpp>

#include "orb/scene/gltf.h"

namespace orb::import_tool {

void add_gltf_options(CLI::App& app, GltfImportOptions& options);

}  // namespace orb::import_tool
