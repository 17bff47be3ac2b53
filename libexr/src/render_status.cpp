#include "orb/exr/render_status.h"

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfTestFile.h>

#include <filesystem>
#include <system_error>

#include "exr_attributes.h"

namespace orb::exr {

RenderStatus inspect_render(const std::string& path) {
    RenderStatus status;
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        status.reason = "no such file";
        return status;
    }
    if (!std::filesystem::is_regular_file(path, ec)) {
        status.reason = "not a regular file";
        return status;
    }
    try {
        bool tiled = false, deep = false, multipart = false;
        if (!Imf::isOpenExrFile(path.c_str(), tiled, deep, multipart) || deep) {
            status.reason = "not an orb-render EXR";
            return status;
        }
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const auto* spp = header.findTypedAttribute<Imf::IntAttribute>(attr::kSpp);
        const auto* target = header.findTypedAttribute<Imf::IntAttribute>(attr::kTargetSpp);
        if (!spp || !target || spp->value() < 1 || target->value() < 1) {
            status.reason = "not an orb-render EXR (no orb:spp and orb:targetSpp)";
            return status;
        }
        status.spp = static_cast<std::uint64_t>(spp->value());
        status.target_spp = static_cast<std::uint64_t>(target->value());
        const Imath::Box2i window = header.dataWindow();
        status.width = window.max.x - window.min.x + 1;
        status.height = window.max.y - window.min.y + 1;
        if (!file.isComplete()) {
            status.reason = "truncated (some scanlines are missing)";
            return status;
        }
        if (status.spp < status.target_spp) {
            status.reason = "stopped at " + std::to_string(status.spp) + " of " + std::to_string(status.target_spp) +
                            " samples per pixel";
            return status;
        }
        status.complete = true;
    } catch (const std::exception& e) {
        status.reason = std::string("unreadable: ") + e.what();
    }
    return status;
}

}  // namespace orb::exr
