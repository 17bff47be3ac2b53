#include "orb/image/display_transform.h"

#include <cmath>

#include "color_config_impl.h"
#include "orb/scene/error.h"

namespace orb::image {
namespace {

void apply_processor(const OCIO::ConstProcessorRcPtr& processor, Image& image) {
    const int n = image.channels();
    if (n < 3) throw InputError("internal: colour transform needs at least three channels");
    auto cpu = processor->getDefaultCPUProcessor();
    // Packed RGB(A) with the pixel stride of the whole image, so extra channels stay untouched.
    OCIO::PackedImageDesc desc(image.pixels.data(), image.width, image.height, OCIO::CHANNEL_ORDERING_RGB,
                               OCIO::BIT_DEPTH_F32, sizeof(float), static_cast<ptrdiff_t>(n * sizeof(float)),
                               static_cast<ptrdiff_t>(n * sizeof(float) * image.width));
    cpu->apply(desc);
}

}  // namespace

DisplayView resolve_display_view(const ColorConfig& config, DisplayView request) {
    if (request.input_space.empty()) {
        request.input_space = config.scene_linear();
    } else {
        const std::string resolved = config.resolve_color_space(request.input_space);
        if (resolved.empty())
            throw InputError("unknown colour space '" + request.input_space + "' in " + config.source());
        request.input_space = resolved;
    }
    if (request.display.empty()) request.display = config.default_display();
    if (request.view.empty()) request.view = config.default_view(request.display);
    config.check_display_view(request.display, request.view);
    config.check_look(request.look);
    return request;
}

void apply_display_view(const ColorConfig& config, const DisplayView& resolved, Image& image) {
    const auto& ocio = config.impl().config;
    OCIO::ConstProcessorRcPtr processor;
    try {
        auto transform = OCIO::DisplayViewTransform::Create();
        transform->setSrc(resolved.input_space.c_str());
        transform->setDisplay(resolved.display.c_str());
        transform->setView(resolved.view.c_str());
        auto pipeline = OCIO::LegacyViewingPipeline::Create();
        pipeline->setDisplayViewTransform(transform);
        if (resolved.exposure_stops != 0.0) {
            // Exposure is a gain in scene-linear, whatever the input space is.
            const double gain = std::exp2(resolved.exposure_stops);
            auto matrix = OCIO::MatrixTransform::Create();
            const double m[16] = {gain, 0, 0, 0, 0, gain, 0, 0, 0, 0, gain, 0, 0, 0, 0, 1};
            matrix->setMatrix(m);
            pipeline->setLinearCC(matrix);
        }
        if (!resolved.look.empty()) {
            pipeline->setLooksOverrideEnabled(true);
            pipeline->setLooksOverride(resolved.look.c_str());
        }
        processor = pipeline->getProcessor(ocio, ocio->getCurrentContext());
    } catch (const OCIO::Exception& e) {
        throw InputError(std::string("OpenColorIO: ") + e.what());
    }

    const bool has_alpha = image.channels() >= 4 && image.channel_names[3] == "A";
    if (has_alpha) {
        for (size_t p = 0; p < image.pixel_count(); ++p) {
            float* px = &image.pixels[p * image.channels()];
            if (px[3] > 0.0f && px[3] != 1.0f)
                for (int c = 0; c < 3; ++c) px[c] /= px[3];
        }
    }
    apply_processor(processor, image);
}

void convert_color_space(const ColorConfig& config, const std::string& from, const std::string& to, Image& image) {
    const auto& ocio = config.impl().config;
    try {
        apply_processor(ocio->getProcessor(from.c_str(), to.c_str()), image);
    } catch (const OCIO::Exception& e) {
        throw InputError(std::string("OpenColorIO: ") + e.what());
    }
}

}  // namespace orb::image
