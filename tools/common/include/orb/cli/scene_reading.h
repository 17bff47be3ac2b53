// The options that shape the scene a tool reads, the same in every tool that
// reads one (orb-import, orb-render, orb-frames --scene; orb-farm hands them
// to orb-render): every importer's option group, as the importer declares it
// (orb/import/importers.h), and --environment with its intensity and rotation.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "orb/cli/environment_options.h"
#include "orb/import/import.h"

namespace orb::cli {

struct SceneReading {
    ImportOptions import;           // the importers' options; the tool sets allow_empty (--allow-empty)
    EnvironmentChoice environment;  // --environment, --environment-intensity, --environment-rotation

    // Each importer option on the tool's command line, with its group's
    // heading, so that one given for another format is named (filled by
    // add_scene_reading_options; read after parsing).
    struct ImporterOption {
        const CLI::Option* option;
        std::string_view heading;
    };
    std::vector<ImporterOption> importer_options;
};

// Adds every importer's option group and the environment's to `app`.
void add_scene_reading_options(CLI::App& app, SceneReading& reading);

// Whether any of them was given on the command line.
bool any_scene_reading_option(const SceneReading& reading);

// The importers' options as the scene is to be read: a chosen environment
// replaces a glTF asset's default light, and glTF textures are decoded
// (through OpenImageIO, loaded when a scene has one).
ImportOptions import_options_for(const SceneReading& reading);

// Warns about each importer option given for another format than the one
// `source` was read as ("ignored --radius (PLY input): the input is read as
// gltf"): it changed nothing.
void warn_about_other_formats_options(const SceneReading& reading, std::string_view format, const std::string& source);

}  // namespace orb::cli
