// Reading any image OpenImageIO understands -- from a file or from stdin
// ("-") -- into one float Image holding every channel of every part.
#pragma once

#include <string>

#include "orb/image/image.h"

namespace orb::image {

struct LoadedImage {
    std::string source;         // the path as the user gave it ("-" shows as <stdin>)
    std::string format_name;    // OIIO's format name, e.g. "openexr", "png"
    std::string color_space;    // the file's oiio:ColorSpace tag, if any
    bool display_referred = false;  // integer pixels (8/16-bit): values are display-encoded
    // The orb:passes header attribute: the layers of an orb-render EXR, whose
    // RGB holds the environment the camera sees where alpha does not cover it
    // (docs/design/background-and-alpha.md); "" for any other file.
    std::string orb_passes;
    // orb:environmentSeen of an orb-render EXR: false when no environment
    // light was behind the spheres, so RGB is premultiplied as it stands.
    bool environment_seen = true;
    Image image;                // all channels, EXR layer names kept ("direct.R")
};

// Throws orb::InputError naming the file for missing, unreadable, malformed
// or truncated images.
LoadedImage load_image(const std::string& path);

// The name used in messages: "<stdin>" for "-".
std::string display_name(const std::string& path);

}  // namespace orb::image
