#include "orb/image/contact_sheet.h"

#include <algorithm>
#include <cmath>

#include "orb/image/passes.h"
#include "orb/image/text.h"
#include "orb/image/visual_mapping.h"
#include "orb/scene/error.h"

namespace orb::image {
namespace {

constexpr float kBackground = 0.12f;

Image tile_for(const Pass& pass, const ColorConfig& config, const DisplayView& view) {
    if (pass.kind != PassKind::Color) return visualize_data_pass(pass);
    Image rgb = select_channels(pass.image, {0, 1, 2}, {"R", "G", "B"});
    DisplayView v = view;
    if (pass.name == "albedo") v.exposure_stops = 0.0;  // reflectance, not light
    apply_display_view(config, v, rgb);
    return rgb;
}

}  // namespace

Image make_contact_sheet(const Image& all_channels, const ColorConfig& config, const DisplayView& view) {
    const std::vector<std::string> names = available_passes(all_channels);
    if (names.empty()) throw InputError("no passes to show");
    const int count = static_cast<int>(names.size());
    const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    const int rows = (count + columns - 1) / columns;
    const int w = all_channels.width, h = all_channels.height;
    const int label = std::clamp(h / 12, 14, 40);
    const int gap = std::max(4, label / 3);
    const int cell_w = w + gap, cell_h = h + label + gap;

    Image sheet(columns * cell_w + gap, rows * cell_h + gap, {"R", "G", "B"}, kBackground);
    for (int i = 0; i < count; ++i) {
        const Pass pass = extract_pass(all_channels, names[i], "contact sheet");
        const Image tile = tile_for(pass, config, view);
        const int ox = gap + (i % columns) * cell_w, oy = gap + (i / columns) * cell_h;
        draw_label(sheet, ox, oy, label, names[i]);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) sheet.at(ox + x, oy + label + y, c) = tile.at(x, y, c);
    }
    return sheet;
}

}  // namespace orb::image
