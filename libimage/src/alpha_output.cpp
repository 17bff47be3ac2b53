#include "orb/image/alpha_output.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "number_text.h"
#include "srgb.h"
#include "orb/scene/error.h"

namespace orb::image {
namespace {

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

[[noreturn]] void bad_color(const std::string& text) {
    throw InputError("--background '" + text +
                     "': expected three linear numbers >= 0 as R,G,B (e.g. 0.18,0.18,0.18) or an sRGB colour #rrggbb");
}

}  // namespace

std::array<float, 3> parse_background_color(const std::string& text) {
    std::array<float, 3> rgb{};
    if (!text.empty() && text[0] == '#') {
        if (text.size() != 7) bad_color(text);
        for (int c = 0; c < 3; ++c) {
            const int hi = hex_digit(text[1 + 2 * c]), lo = hex_digit(text[2 + 2 * c]);
            if (hi < 0 || lo < 0) bad_color(text);
            rgb[c] = srgb_to_linear(static_cast<float>(hi * 16 + lo) / 255.0f);
        }
        return rgb;
    }
    size_t start = 0;
    for (int c = 0; c < 3; ++c) {
        const size_t comma = text.find(',', start);
        if ((c < 2) != (comma != std::string::npos)) bad_color(text);
        const auto value = parse_double(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        // A float gain stays finite: the values are light, so at most FLT_MAX.
        if (!value || !std::isfinite(*value) || *value < 0.0 || *value > 3.4e38) bad_color(text);
        rgb[c] = static_cast<float>(*value);
        start = comma + 1;
    }
    return rgb;
}

std::string alpha_output_text(const AlphaOutput& output) {
    switch (output.mode) {
        case AlphaMode::Opaque: return "opaque";
        case AlphaMode::Transparent: return "transparent";
        case AlphaMode::OverColor:
            return "over " + shortest_text(output.background[0]) + "," + shortest_text(output.background[1]) + "," +
                   shortest_text(output.background[2]);
    }
    return "opaque";
}

Pass prepare_alpha(const Pass& pass, const LoadedImage& loaded, const AlphaOutput& output) {
    if (!pass.has_alpha || pass.image.channels() != 4) return pass;
    Pass out = pass;
    out.has_alpha = false;
    if (output.mode == AlphaMode::Opaque) {
        out.image = select_channels(pass.image, {0, 1, 2}, {"R", "G", "B"});
        return out;
    }

    const Image& rgba = pass.image;
    const size_t n = rgba.pixel_count();
    // The environment the camera saw, to take out of RGB: orb-render's
    // background layer; nothing for other files, whose RGB is premultiplied,
    // nor for an orb-render image of a scene without environment light.
    const bool from_orb_render = !loaded.orb_passes.empty();
    std::optional<Pass> background;
    if (from_orb_render) {
        const std::vector<std::string> present = available_passes(loaded.image);
        if (std::find(present.begin(), present.end(), "background") != present.end())
            background = extract_pass(loaded.image, "background", display_name(loaded.source));
    }
    if (from_orb_render && !background && loaded.environment_seen) {
        for (size_t p = 0; p < n; ++p)
            if (rgba.pixels[p * 4 + 3] < 1.0f)
                throw InputError(display_name(loaded.source) +
                                 ": its RGB includes the environment the camera sees where A < 1, and it has no "
                                 "background layer to take it out; render it with --passes beauty,background to "
                                 "make it " + alpha_output_text(output) + " (or leave the image opaque)");
    }

    Image image(rgba.width, rgba.height, output.mode == AlphaMode::Transparent
                                             ? std::vector<std::string>{"R", "G", "B", "A"}
                                             : std::vector<std::string>{"R", "G", "B"});
    const int channels = image.channels();
    for (size_t p = 0; p < n; ++p) {
        const float* in = &rgba.pixels[p * 4];
        const float alpha = in[3];
        float foreground[3];
        for (int c = 0; c < 3; ++c) {
            foreground[c] = in[c];
            if (background) foreground[c] = std::max(0.0f, in[c] - background->image.pixels[p * 3 + c]);
            // Nothing covers the pixel: no colour of its own (RGB - background is 0 but for rounding).
            if (background && alpha <= 0.0f) foreground[c] = 0.0f;
        }
        float* px = &image.pixels[p * channels];
        if (output.mode == AlphaMode::Transparent) {
            for (int c = 0; c < 3; ++c) px[c] = foreground[c];
            px[3] = alpha;
        } else {
            const float uncovered = std::clamp(1.0f - alpha, 0.0f, 1.0f);
            for (int c = 0; c < 3; ++c) px[c] = foreground[c] + uncovered * output.background[c];
        }
    }
    out.image = std::move(image);
    out.has_alpha = output.mode == AlphaMode::Transparent;
    return out;
}

}  // namespace orb::image
