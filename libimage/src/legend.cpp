#include "orb/image/legend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "orb/image/text.h"
#include "orb/image/write.h"

namespace orb::image {
namespace {

constexpr std::array<float, 3> kInk = {0.0f, 0.0f, 0.0f};
constexpr std::array<float, 3> kFrame = {0.5f, 0.5f, 0.5f};  // around bars and swatches: a white colour still shows
constexpr int kMargin = 12;
constexpr int kTitleHeight = 20;   // the property's name
constexpr int kTextHeight = 16;    // values and labels
constexpr int kBarLength = 256;    // pixels from one end of the map to the other
constexpr int kBarThickness = 28;
constexpr int kTickLength = 6;
constexpr int kTicks = 5;          // the ends and three between
constexpr int kSwatch = 16;
constexpr int kRowPitch = 24;          // a category's row
constexpr int kCategoriesPerLine = 20; // vertical: rows per column; horizontal: entries per row (of 8)
constexpr int kCategoriesPerRow = 8;

// Four significant digits: enough to read a tick, short enough to fit.
std::string value_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value == 0 ? 0.0 : value);  // never "-0"
    return text;
}

void fill(Image& image, const PixelBox& box, const std::array<float, 3>& color) {
    for (int y = std::max(0, box.y0); y < std::min(image.height, box.y1); ++y)
        for (int x = std::max(0, box.x0); x < std::min(image.width, box.x1); ++x)
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = color[c];
}

// A one-pixel line just outside `box`.
void outline(Image& image, const PixelBox& box) {
    fill(image, {box.x0 - 1, box.y0 - 1, box.x1 + 1, box.y0}, kFrame);
    fill(image, {box.x0 - 1, box.y1, box.x1 + 1, box.y1 + 1}, kFrame);
    fill(image, {box.x0 - 1, box.y0, box.x0, box.y1}, kFrame);
    fill(image, {box.x1, box.y0, box.x1 + 1, box.y1}, kFrame);
}

Image blank(int width, int height) { return Image(width, height, {"R", "G", "B"}, 1.0f); }

// The values at the ticks, from range.first to range.second (one when they are equal).
std::vector<double> tick_values(const std::pair<double, double>& range) {
    if (!(range.first < range.second)) return {range.first};
    std::vector<double> values;
    for (int k = 0; k < kTicks; ++k)
        values.push_back(k == kTicks - 1 ? range.second
                                         : range.first + (range.second - range.first) * k / (kTicks - 1));
    return values;
}

// Where tick k of n lies along the bar, as a position 0..1 on the map.
double tick_position(std::size_t k, std::size_t n) { return n == 1 ? 0.5 : static_cast<double>(k) / (n - 1); }

void paint_bar(LegendImage& legend, const ColorLegend& spec, LegendOrientation orientation) {
    const PixelBox& bar = legend.bar;
    for (int y = bar.y0; y < bar.y1; ++y)
        for (int x = bar.x0; x < bar.x1; ++x) {
            const std::array<float, 3> color = colormap_display_color(spec.colormap, bar_position(legend, orientation, x, y));
            for (int c = 0; c < 3; ++c) legend.image.at(x, y, c) = color[c];
        }
    outline(legend.image, bar);
}

LegendImage numeric_vertical(const ColorLegend& spec) {
    const std::vector<double> ticks = tick_values(spec.range);
    int widest = 0;
    for (double value : ticks) widest = std::max(widest, label_width(kTextHeight, value_text(value)));
    const int top = kMargin + kTitleHeight + kTextHeight / 2 + 4;  // room for the top tick's label
    LegendImage legend;
    legend.bar = {kMargin, top, kMargin + kBarThickness, top + kBarLength};
    const int text_x = legend.bar.x1 + kTickLength + 4;
    const int width = std::max(text_x + widest, kMargin + label_width(kTitleHeight, spec.property)) + kMargin;
    legend.image = blank(width, legend.bar.y1 + kTextHeight / 2 + kMargin);
    draw_label(legend.image, kMargin, kMargin - 4, kTitleHeight, spec.property, kInk);
    paint_bar(legend, spec, LegendOrientation::Vertical);
    for (std::size_t k = 0; k < ticks.size(); ++k) {
        const int y = legend.bar.y1 - 1 - static_cast<int>(std::lround(tick_position(k, ticks.size()) * (kBarLength - 1)));
        fill(legend.image, {legend.bar.x1 + 1, y, legend.bar.x1 + 1 + kTickLength, y + 1}, kInk);
        draw_label(legend.image, text_x, y - kTextHeight / 2, kTextHeight, value_text(ticks[k]), kInk);
    }
    return legend;
}

LegendImage numeric_horizontal(const ColorLegend& spec) {
    const std::vector<double> ticks = tick_values(spec.range);
    std::vector<int> widths;
    for (double value : ticks) widths.push_back(label_width(kTextHeight, value_text(value)));
    // The end labels are centred on the ends: room for their halves.
    const int left = std::max(kMargin, widths.front() / 2 + 4);
    const int right = std::max(kMargin, widths.back() / 2 + 4);
    const int top = kMargin + kTitleHeight + 4;
    LegendImage legend;
    legend.bar = {left, top, left + kBarLength, top + kBarThickness};
    const int text_y = legend.bar.y1 + 1 + kTickLength + 2;
    const int width = std::max(legend.bar.x1 + right, kMargin + label_width(kTitleHeight, spec.property) + kMargin);
    legend.image = blank(width, text_y + kTextHeight + kMargin);
    draw_label(legend.image, kMargin, kMargin - 4, kTitleHeight, spec.property, kInk);
    paint_bar(legend, spec, LegendOrientation::Horizontal);
    for (std::size_t k = 0; k < ticks.size(); ++k) {
        const int x = legend.bar.x0 + static_cast<int>(std::lround(tick_position(k, ticks.size()) * (kBarLength - 1)));
        fill(legend.image, {x, legend.bar.y1 + 1, x + 1, legend.bar.y1 + 1 + kTickLength}, kInk);
        draw_label(legend.image, x - widths[k] / 2, text_y, kTextHeight, value_text(ticks[k]), kInk);
    }
    return legend;
}

// Swatches in a grid: vertical fills columns of kCategoriesPerLine rows,
// horizontal rows of kCategoriesPerRow entries.
LegendImage categorical(const ColorLegend& spec, LegendOrientation orientation) {
    const std::size_t n = spec.categories.size();
    int widest = 0;
    for (const ColorLegend::Category& category : spec.categories)
        widest = std::max(widest, label_width(kTextHeight, category.label));
    const int cell_width = kSwatch + 8 + widest + 16;
    const std::size_t per_line = orientation == LegendOrientation::Vertical ? kCategoriesPerLine : kCategoriesPerRow;
    const std::size_t lines = std::max<std::size_t>(1, (n + per_line - 1) / per_line);
    const std::size_t rows = orientation == LegendOrientation::Vertical ? std::min(n, per_line) : lines;
    const std::size_t columns = orientation == LegendOrientation::Vertical ? lines : std::min(n, per_line);
    const int top = kMargin + kTitleHeight + 8;
    const int width = std::max(kMargin + static_cast<int>(columns) * cell_width - 16,
                               kMargin + label_width(kTitleHeight, spec.property)) + kMargin;
    LegendImage legend;
    legend.image = blank(width, top + static_cast<int>(std::max<std::size_t>(rows, 1)) * kRowPitch + kMargin);
    draw_label(legend.image, kMargin, kMargin - 4, kTitleHeight, spec.property, kInk);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t row = orientation == LegendOrientation::Vertical ? k % per_line : k / per_line;
        const std::size_t column = orientation == LegendOrientation::Vertical ? k / per_line : k % per_line;
        const int x = kMargin + static_cast<int>(column) * cell_width;
        const int y = top + static_cast<int>(row) * kRowPitch;
        const PixelBox swatch{x, y + (kRowPitch - kSwatch) / 2, x + kSwatch, y + (kRowPitch - kSwatch) / 2 + kSwatch};
        fill(legend.image, swatch, spec.categories[k].display_color);
        outline(legend.image, swatch);
        legend.swatches.push_back(swatch);
        draw_label(legend.image, x + kSwatch + 8, y + (kRowPitch - kTextHeight) / 2, kTextHeight,
                   spec.categories[k].label, kInk);
    }
    return legend;
}

}  // namespace

LegendImage draw_legend(const ColorLegend& legend, LegendOrientation orientation) {
    if (legend.categorical) return categorical(legend, orientation);
    return orientation == LegendOrientation::Vertical ? numeric_vertical(legend) : numeric_horizontal(legend);
}

double bar_position(const LegendImage& legend, LegendOrientation orientation, int x, int y) {
    const PixelBox& bar = legend.bar;
    if (orientation == LegendOrientation::Vertical)
        return static_cast<double>(bar.y1 - 1 - y) / std::max(1, bar.y1 - bar.y0 - 1);
    return static_cast<double>(x - bar.x0) / std::max(1, bar.x1 - bar.x0 - 1);
}

std::string encode_legend_png(const ColorLegend& legend, LegendOrientation orientation) {
    WriteOptions options;
    options.format = "png";
    options.bits = 8;
    options.dither = false;  // flat colours stay flat: each pixel is the map's colour rounded
    return encode_image(draw_legend(legend, orientation).image, checked_write_options(options));
}

}  // namespace orb::image
