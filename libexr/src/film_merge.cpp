#include "orb/exr/film_merge.h"

#include <algorithm>
#include <sstream>

#include "orb/scene/error.h"

namespace orb::exr {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& message) {
    throw InputError(path + ": " + message);
}

// A setting every slice of one render shares.
template <typename T>
void require_same(const MergeInput& input, const MergeInput& reference, const char* what, const T& value,
                  const T& expected) {
    if (value == expected) return;
    std::ostringstream message;
    message << what << " " << value << " differs from " << reference.path << "'s " << expected
            << "; only slices of the same render merge";
    fail(input.path, message.str());
}

void check_same_render(const MergeInput& input, const MergeInput& reference) {
    const ExrMetadata& m = input.file.metadata;
    const ExrMetadata& r = reference.file.metadata;
    require_same(input, reference, "the width", input.file.film.width, reference.file.film.width);
    require_same(input, reference, "the height", input.file.film.height, reference.file.film.height);
    require_same(input, reference, "orb:seed", m.seed, r.seed);
    require_same(input, reference, "orb:sceneHash", m.scene_hash, r.scene_hash);
    require_same(input, reference, "orb:sceneTime", m.scene_time, r.scene_time);
    require_same(input, reference, "orb:mode", m.mode, r.mode);
    require_same(input, reference, "orb:sampler", m.sampler, r.sampler);
    require_same(input, reference, "orb:maxDepth", m.max_depth, r.max_depth);
    require_same(input, reference, "orb:passes", format_passes(input.file.passes),
                 format_passes(reference.file.passes));
    // Samples of different kernels (orb/render/kernel_identity.h) are not one render's.
    const auto named = [](const std::string& kernel) { return kernel.empty() ? std::string("(none)") : kernel; };
    require_same(input, reference, "orb:kernel", named(m.kernel), named(r.kernel));
}

std::string joined_devices(const std::vector<MergeInput>& inputs) {
    std::vector<std::string> devices;
    for (const MergeInput& input : inputs)
        if (std::find(devices.begin(), devices.end(), input.file.metadata.device) == devices.end())
            devices.push_back(input.file.metadata.device);
    std::string text;
    for (const std::string& device : devices) text += (text.empty() ? "" : "; ") + device;
    return text;
}

}  // namespace

ExrFilm merge_films(std::vector<MergeInput> inputs) {
    if (inputs.empty()) throw std::invalid_argument("nothing to merge");
    for (const MergeInput& input : inputs)
        if (input.file.half)
            fail(input.path,
                 "was written with --half; merging within float rounding needs FLOAT channels (render the slices "
                 "without --half)");

    // In sample order: the slice holding the lowest sample index is the
    // reference (its header, and the centre-ray channels), whatever the
    // order of the arguments; the sums add exactly in any order.
    std::stable_sort(inputs.begin(), inputs.end(), [](const MergeInput& a, const MergeInput& b) {
        return a.file.film.sample_ranges.first() < b.file.film.sample_ranges.first();
    });
    const MergeInput& reference = inputs.front();
    for (std::size_t i = 1; i < inputs.size(); ++i) {
        check_same_render(inputs[i], reference);
        for (std::size_t j = 0; j < i; ++j)
            if (inputs[j].file.film.sample_ranges.overlaps(inputs[i].file.film.sample_ranges))
                fail(inputs[i].path, "its samples " + inputs[i].file.film.sample_ranges.format() + " overlap " +
                                         inputs[j].path + "'s " + inputs[j].file.film.sample_ranges.format() +
                                         "; each sample may be merged once");
    }

    ExrFilm merged = reference.file;
    for (std::size_t i = 1; i < inputs.size(); ++i) {
        merged.film.accumulate(inputs[i].file.film);
        merged.metadata.target_spp += inputs[i].file.metadata.target_spp;
        merged.metadata.render_seconds += inputs[i].file.metadata.render_seconds;
        merged.exact = merged.exact && inputs[i].file.exact;
    }
    merged.metadata.device = joined_devices(inputs);
    return merged;
}

}  // namespace orb::exr
