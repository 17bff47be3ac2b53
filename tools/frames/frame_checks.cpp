#include "frame_checks.h"

#include "orb/exr/render_status.h"

namespace orb::frames {

std::string why_not_done(const std::string& path, const FrameRequirements& wanted) {
    const exr::RenderStatus status = exr::inspect_render(path);
    if (!status.complete) return status.reason;
    if (wanted.spp && status.spp != *wanted.spp)
        return "has " + std::to_string(status.spp) + " samples per pixel, not " + std::to_string(*wanted.spp);
    if (wanted.samples && status.sample_ranges != *wanted.samples)
        return "holds samples " + status.sample_ranges + ", not " + *wanted.samples;
    if ((wanted.width && status.width != *wanted.width) || (wanted.height && status.height != *wanted.height))
        return "is " + std::to_string(status.width) + "x" + std::to_string(status.height) + ", not " +
               (wanted.width ? std::to_string(*wanted.width) : std::to_string(status.width)) + "x" +
               (wanted.height ? std::to_string(*wanted.height) : std::to_string(status.height));
    return "";
}

}  // namespace orb::frames
