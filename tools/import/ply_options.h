// orb-import's PLY options (docs/orb-import.md, "PLY point clouds").
#pragma once

#include <CLI/CLI.hpp>

#include "orb/scene/ply.h"

namespace orb::import_tool {

void add_ply_options(CLI::App& app, PlyImportOptions& options);

}  // namespace orb::import_tool
