#include "orb/image/tonemap.h"

#include "orb/image/visual_mapping.h"

namespace orb::image {

Image tonemap_pass(const Pass& pass, const ColorConfig& config, const DisplayView& view) {
    if (pass.kind != PassKind::Color) return visualize_data_pass(pass);
    Image image = pass.image;
    apply_display_view(config, view, image);
    return image;
}

}  // namespace orb::image
