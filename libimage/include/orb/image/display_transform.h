// Applying colour transforms to Images in place through OpenColorIO.
#pragma once

#include <string>

#include "orb/image/color_config.h"
#include "orb/image/image.h"

namespace orb::image {

struct DisplayView {
    std::string input_space;  // empty: the config's scene_linear role
    std::string display;      // empty: the config's default display
    std::string view;         // empty: that display's default view
    std::string look;         // empty: the view's own looks; otherwise overrides them
    double exposure_stops = 0.0;  // applied in scene-linear before the view
};

// Fills empty fields with the config's defaults and validates the choices.
DisplayView resolve_display_view(const ColorConfig& config, DisplayView request);

// Scene values -> display-encoded values. The first three channels are RGB;
// a fourth (alpha) is passed through, with colour un-premultiplied first
// (as OIIO's --ociodisplay does) so that partial coverage is not darkened twice.
void apply_display_view(const ColorConfig& config, const DisplayView& resolved, Image& rgb);

// Colour space conversion of the first three channels.
void convert_color_space(const ColorConfig& config, const std::string& from, const std::string& to, Image& rgb);

}  // namespace orb::image
