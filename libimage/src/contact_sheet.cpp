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

int SheetGeometry::picture_x(int index) const { return gap + (index % columns) * (tile_width + gap); }
int SheetGeometry::picture_y(int index) const {
    return gap + (index / columns) * (tile_height + label_height + gap) + label_height;
}

SheetGeometry sheet_geometry(int count, int tile_width, int tile_height) {
    SheetGeometry g;
    g.columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
    g.rows = (count + g.columns - 1) / g.columns;
    g.tile_width = tile_width;
    g.tile_height = tile_height;
    g.label_height = std::clamp(tile_height / 12, 14, 40);
    g.gap = std::max(4, g.label_height / 3);
    g.sheet_width = g.columns * (tile_width + g.gap) + g.gap;
    g.sheet_height = g.rows * (tile_height + g.label_height + g.gap) + g.gap;
    return g;
}

Image lay_out_sheet(const std::vector<SheetTile>& tiles) {
    if (tiles.empty()) throw InputError("no pictures to lay out in a contact sheet");
    const int w = tiles[0].picture.width, h = tiles[0].picture.height;
    for (const SheetTile& tile : tiles)
        if (tile.picture.width != w || tile.picture.height != h)
            throw InputError("contact sheet: " + tile.label + " is " + std::to_string(tile.picture.width) + "x" +
                             std::to_string(tile.picture.height) + ", " + tiles[0].label + " " + std::to_string(w) +
                             "x" + std::to_string(h) + "; a sheet's pictures must have one size");
    const int count = static_cast<int>(tiles.size());
    const SheetGeometry g = sheet_geometry(count, w, h);
    Image sheet(g.sheet_width, g.sheet_height, {"R", "G", "B"}, kBackground);
    for (int i = 0; i < count; ++i) {
        const int ox = g.picture_x(i), oy = g.picture_y(i);
        draw_label(sheet, ox, oy - g.label_height, g.label_height, tiles[i].label);
        const Image& picture = tiles[i].picture;
        const int n = picture.channels();
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) sheet.at(ox + x, oy + y, c) = picture.at(x, y, std::min(c, n - 1));
    }
    return sheet;
}

Image make_contact_sheet(const Image& all_channels, const ColorConfig& config, const DisplayView& view) {
    const std::vector<std::string> names = available_passes(all_channels);
    if (names.empty()) throw InputError("no passes to show");
    std::vector<SheetTile> tiles;
    for (const std::string& name : names)
        tiles.push_back({name, tile_for(extract_pass(all_channels, name, "contact sheet"), config, view)});
    return lay_out_sheet(tiles);
}

Image box_downscale(const Image& image, int factor) {
    if (factor <= 1) return image;
    const int w = (image.width + factor - 1) / factor, h = (image.height + factor - 1) / factor;
    const int n = image.channels();
    Image out(w, h, image.channel_names);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int x0 = x * factor, y0 = y * factor;
            const int x1 = std::min(image.width, x0 + factor), y1 = std::min(image.height, y0 + factor);
            const float count = static_cast<float>((x1 - x0) * (y1 - y0));
            for (int c = 0; c < n; ++c) {
                double sum = 0.0;
                for (int yy = y0; yy < y1; ++yy)
                    for (int xx = x0; xx < x1; ++xx) sum += image.at(xx, yy, c);
                out.at(x, y, c) = static_cast<float>(sum / count);
            }
        }
    return out;
}

Image nearest_downscale(const Image& image, int factor) {
    if (factor <= 1) return image;
    const int w = (image.width + factor - 1) / factor, h = (image.height + factor - 1) / factor;
    Image out(w, h, image.channel_names);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < image.channels(); ++c) out.at(x, y, c) = image.at(x * factor, y * factor, c);
    return out;
}

}  // namespace orb::image
