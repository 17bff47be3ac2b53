// The legend writer as a module the tools load only for --legend
// (orb/cli/legend_output.h), so that orb-render, orb-import and orb-frames do
// not link OpenImageIO (docs/design/texture-decoding.md says why). The entry
// point takes C++ types: the module is built and installed with the tools
// from the same source, never mixed with another build.
#include <exception>
#include <string>

#include "orb/image/legend.h"

extern "C" __attribute__((visibility("default"))) bool orb_encode_legend_v1(const orb::ColorLegend& legend,
                                                                           bool horizontal, std::string& png,
                                                                           std::string& error) noexcept {
    try {
        png = orb::image::encode_legend_png(
            legend, horizontal ? orb::image::LegendOrientation::Horizontal : orb::image::LegendOrientation::Vertical);
        return true;
    } catch (const std::exception& e) {
        error = e.what();
    } catch (...) {
        error = "the legend could not be drawn";
    }
    return false;
}
