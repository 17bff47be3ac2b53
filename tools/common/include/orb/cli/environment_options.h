// The --environment options of every tool that reads a scene: light the
// scene from infinitely far away (a uniform colour or an HDR map), as a glTF
// viewer's or Blender's world does, without editing the scene file
// (docs/orb-import.md, "Environment").
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "orb/scene/scene.h"

namespace orb::cli {

struct EnvironmentChoice {
    std::string value;        // "R,G,B" or "V": a uniform radiance; else an OpenEXR map's path; empty: none
    double intensity = 1.0;   // multiplies the map's texels (or the colour)
    double rotation_deg = 0.0;  // the map's turn about +y
};

void add_environment_options(CLI::App& app, EnvironmentChoice& choice);

// The environment chosen, or nothing when --environment was not given. A
// map's path, relative to the current directory on the command line, is
// given relative to `scene_dir` (the folder the scene is read from: where
// orb-import writes it, where orb-render resolves the scene's own paths).
// Throws InputError for radiance out of range, a missing map or a file that
// is not OpenEXR.
std::optional<Environment> chosen_environment(const EnvironmentChoice& choice, const std::string& scene_dir);

}  // namespace orb::cli
