#include "orb/image/compare.h"

#include "orb/image/heatmap.h"
#include "orb/scene/error.h"

namespace orb::image {
namespace {

std::string dims(const Image& i) { return std::to_string(i.width) + "x" + std::to_string(i.height); }

Image rgb_only(const Image& image) { return select_channels(image, {0, 1, 2}, {"R", "G", "B"}); }

// A colour pass in the comparison space.
Image prepare_color(const LoadedImage& source, const Pass& pass, const CompareSettings& s) {
    Image rgb = rgb_only(pass.image);
    if (source.display_referred) return rgb;  // already display-encoded values
    const ColorConfig& config = *s.config;
    if (s.through_display) {
        DisplayView request = s.view;
        request.input_space = s.input_space;
        apply_display_view(config, resolve_display_view(config, request), rgb);
        return rgb;
    }
    if (!s.input_space.empty()) {
        const std::string from = config.resolve_color_space(s.input_space);
        if (from.empty()) throw InputError("unknown colour space '" + s.input_space + "' in " + config.source());
        const std::string to = config.scene_linear();
        if (from != to) convert_color_space(config, from, to, rgb);
    }
    return rgb;
}

}  // namespace

PassComparison compare_pass(const LoadedImage& reference, const LoadedImage& test, const std::string& pass_name,
                            const CompareSettings& s) {
    const Pass ref_pass = extract_pass(reference.image, pass_name, display_name(reference.source));
    const Pass test_pass =
        extract_pass(test.image, s.test_pass.empty() ? pass_name : s.test_pass, display_name(test.source));
    if (test_pass.kind != ref_pass.kind)
        throw InputError("cannot compare " + display_name(reference.source) + "'s " + ref_pass.name + " (" +
                         kind_name(ref_pass.kind) + ") with " + display_name(test.source) + "'s " + test_pass.name +
                         " (" + kind_name(test_pass.kind) + ")");
    if (ref_pass.image.width != test_pass.image.width || ref_pass.image.height != test_pass.image.height)
        throw InputError("images differ in size: " + display_name(reference.source) + " is " + dims(ref_pass.image) +
                         ", " + display_name(test.source) + " is " + dims(test_pass.image));

    PassComparison result;
    result.pass = ref_pass.name == test_pass.name ? ref_pass.name : ref_pass.name + " vs " + test_pass.name;
    result.kind = ref_pass.kind;
    result.width = ref_pass.image.width;
    result.height = ref_pass.image.height;
    const double ppd = s.ppd > 0 ? s.ppd : default_flip_ppd();

    Image a, b;
    if (ref_pass.kind == PassKind::Color) {
        if (reference.display_referred != test.display_referred && !s.through_display)
            throw InputError(display_name(reference.display_referred ? reference.source : test.source) +
                             " is a display-encoded 8/16-bit image but " +
                             display_name(reference.display_referred ? test.source : reference.source) +
                             " holds scene-linear floats; pass --display/--view to compare both as displayed");
        a = prepare_color(reference, ref_pass, s);
        b = prepare_color(test, test_pass, s);
        const bool display_values = s.through_display || reference.display_referred;
        if (s.through_display)
            result.space = "display: " + s.view.display + " / " + s.view.view;
        else
            result.space = display_values ? "display-encoded" : "scene-linear";
        result.flip = display_values ? flip_ldr(a, b, ppd) : flip_hdr(a, b, ppd);
    } else {
        if (ref_pass.image.channels() != test_pass.image.channels())
            throw InputError("pass '" + ref_pass.name + "' has different channels in the two images");
        a = ref_pass.image;
        b = test_pass.image;
        result.space = "data";
    }
    result.channels = a.channel_names;
    result.stats = compute_error_stats(a, b);
    for (const Tolerance& t : s.thresholds) result.percent_over.push_back(percent_pixels_over(a, b, t));
    if (s.want_heatmap)
        result.heatmap = result.flip ? magma_heatmap(result.flip->error, result.width, result.height)
                                     : normalized_heatmap(a, b);
    return result;
}

}  // namespace orb::image
