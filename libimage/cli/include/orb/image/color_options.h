// The colour-management options every Orb colour tool offers, parsed the same
// way everywhere: --config, --display, --view, --look, --input-space, --list.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "orb/image/color_config.h"
#include "orb/image/display_transform.h"
#include "orb/image/load.h"

namespace orb::image {

struct ColorOptions {
    std::string config_path;
    std::string display;
    std::string view;
    std::string look;
    std::string input_space;
    bool list = false;
};

void add_color_options(CLI::App& app, ColorOptions& options);

// --config, else $OCIO, else <share>/ocio/config.ocio.
ColorConfig load_color_config(const ColorOptions& options);

// The colour space an image's colour passes are in: --input-space if given,
// else the sRGB space for 8/16-bit files, else scene_linear.
std::string input_space_for(const ColorConfig& config, const ColorOptions& options, const LoadedImage& image);

}  // namespace orb::image
