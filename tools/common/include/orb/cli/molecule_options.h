// The options of the molecular and particle readers (orb/scene/molecular.h),
// shared by orb-import and orb-render so the same words build the same scene
// (docs/orb-import.md, "Molecules and particles").
#pragma once

#include <CLI/CLI.hpp>

#include "orb/scene/molecular.h"

namespace orb::cli {

// `with_frame`: also --frame N (orb-import writes one frame; orb-render has its own --frame/--frames).
void add_molecule_options(CLI::App& app, MolecularImportOptions& options, bool with_frame);

}  // namespace orb::cli
