// The settings that shape a display image's pixels, as orb-tonemap resolves
// them: two images made from the same source with equal settings have the
// same pixels. --skip-existing compares the settings an image was made with
// against those asked for now.
#pragma once

#include <string>
#include <vector>

namespace orb::image {

struct DisplaySettings {
    bool contact_sheet = false;
    std::string pass;         // --pass as given ("" for a contact sheet)
    std::string input_space;  // --input-space resolved to its canonical name; "" = the source's own default
    std::string display;      // resolved: the config's default display when not given
    std::string view;         // resolved: the display's default view when not given
    std::string look;         // --look as given; "" = the view's own looks
    double exposure = 0.0;    // stops (with auto_exposure: added to the automatic exposure)
    bool auto_exposure = false;  // --auto-exposure (the stops it comes to follow from the source's pixels)
    std::string alpha = "opaque";  // alpha_output_text: "opaque", "transparent" or "over R,G,B"
    std::string config;       // identity of the colour config's content (ColorConfig::content_hash)
    std::string format;       // normalised output format: "png", "jpg", "tif", "exr", ...
    int bits = 0;             // resolved bits per channel
    bool dither = false;      // dithered 8-bit quantisation (false at 16 and 32 bits, where it never applies)

    bool operator==(const DisplaySettings&) const = default;
};

// How `made` differs from `asked`, one phrase per difference in the words of
// the command line, e.g. "made with --exposure 0, 1 asked"; empty when equal.
std::vector<std::string> settings_differences(const DisplaySettings& made, const DisplaySettings& asked);

}  // namespace orb::image
