// A scene names its environment map relative to its own folder, so a scene
// written somewhere else must name the map relative to its new folder.
#pragma once

#include <string>

#include "orb/scene/scene.h"

namespace orb::cli {

// A map path relative to `input_dir`, as it must be written relative to
// `output_dir` so that it names the same file; absolute paths unchanged.
std::string rebased_map_path(const std::string& map, const std::string& input_dir, const std::string& output_dir);

// Rewrites a relative environment map path of a scene read from `input_dir`
// so that it names the same file from `output_dir` (both as the tools
// resolve them: a scene's folder, or the current directory for stdin and
// stdout). Absolute paths and scenes without a map are left alone.
void rebase_environment_map(Scene& scene, const std::string& input_dir, const std::string& output_dir);

}  // namespace orb::cli
