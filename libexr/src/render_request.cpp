#include "orb/exr/render_request.h"

#include "orb/exr/camera_matrices.h"

#include <sstream>

namespace orb::exr {
namespace {

template <typename T>
std::string text(const T& value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

}  // namespace

std::string another_kernel(const std::string& file_kernel, const std::string& kernel) {
    return file_kernel.empty() ? "rendered by kernels it does not name (no orb:kernel: an older Orb), these are " + kernel
                               : "rendered by other kernels (orb:kernel " + file_kernel + ", these are " + kernel + ")";
}

namespace {

OutputJudgement different(std::string reason, std::uint64_t held) {
    return {OutputState::Different, std::move(reason), held};
}

// The first setting the file was rendered with that differs from the
// request, cheapest checks first; empty when all agree.
std::string mismatch(const ExrFilmSummary& file, const RenderRequest& r) {
    const ExrMetadata& m = file.metadata;
    if (r.kernel && *r.kernel != m.kernel) return another_kernel(m.kernel, *r.kernel);
    if ((r.width && *r.width != file.width) || (r.height && *r.height != file.height))
        return "rendered at " + text(file.width) + "x" + text(file.height) + ", " + text(r.width.value_or(file.width)) +
               "x" + text(r.height.value_or(file.height)) + " asked";
    if (r.passes && *r.passes != file.passes)
        return "holds the layers '" + format_passes(file.passes) + "', '" + format_passes(*r.passes) + "' asked";
    if (r.half && *r.half != file.half)
        return file.half ? "stored as HALF (--half), FLOAT asked" : "stored as FLOAT, HALF (--half) asked";
    if (r.mode && *r.mode != m.mode) return "rendered with --mode " + m.mode + ", " + *r.mode + " asked";
    if (r.sampler && *r.sampler != m.sampler) return "rendered with --sampler " + m.sampler + ", " + *r.sampler + " asked";
    if (r.max_depth && *r.max_depth != m.max_depth)
        return "rendered with --max-depth " + text(m.max_depth) + ", " + text(*r.max_depth) + " asked";
    if (r.seed && *r.seed != m.seed)
        return "rendered with another seed (orb:seed " + text(m.seed) + ", " + text(*r.seed) + " asked)";
    if (r.adaptive) {
        const auto setting = [](const std::optional<double>& value) { return value ? text(*value) : std::string("none"); };
        if (r.adaptive->noise_threshold != m.noise_threshold)
            return "rendered with --noise-threshold " + setting(m.noise_threshold) + ", " +
                   setting(r.adaptive->noise_threshold) + " asked";
        if (r.adaptive->target_error != m.target_error)
            return "rendered with --target-error " + setting(m.target_error) + ", " + setting(r.adaptive->target_error) +
                   " asked";
    }
    if (r.scene_time && *r.scene_time != m.scene_time)
        return "rendered at scene time " + text(m.scene_time) + " s, " + text(*r.scene_time) + " s asked";
    if (r.scene) {
        const SceneIdentity now = r.scene();
        // The camera is part of the scene, so a moved camera changes the hash too; it is named first.
        if (is_orthographic(now.world_to_ndc) != is_orthographic(m.world_to_ndc))
            return is_orthographic(m.world_to_ndc)
                       ? "rendered from another camera (orthographic, a perspective one asked)"
                       : "rendered from another camera (perspective, an orthographic one asked)";
        if (now.world_to_camera != m.world_to_camera || now.world_to_ndc != m.world_to_ndc)
            return "rendered from another camera (its worldToCamera or worldToNDC differs)";
        if (now.hash != m.scene_hash)
            return "rendered from another scene (orb:sceneHash " + m.scene_hash + ", the scene now hashes to " +
                   now.hash + ")";
    }
    return "";
}

OutputJudgement judge_samples(const ExrFilmSummary& file, const RenderRequest& r) {
    const SampleRanges& held = file.sample_ranges;
    const std::uint64_t n = held.total();
    const bool one_range = held.ranges().size() == 1;
    // Half floats lose the sums: more samples cannot be added within float rounding.
    const auto continuable = [&](std::string reason) {
        if (file.half) return different(reason + ", stored as HALF, which cannot be continued exactly", n);
        return OutputJudgement{OutputState::Continuable, std::move(reason), n};
    };
    // An adaptive render that ended on its rule before the samples asked
    // for holds what it needs (every pixel below the noise threshold, or the
    // frame below the target error): continuing it would decide the same and stop.
    const bool stopped_on_its_rule = file.metadata.adaptive_stop.has_value();
    if (r.slice) {
        const std::uint64_t count = r.spp.value_or(file.metadata.target_spp);
        const SampleRange asked{r.first_sample, count};
        if (one_range && held.ranges().front() == asked) return {OutputState::Finished, "", n};
        if (one_range && held.first() == asked.first && held.end() < asked.end() && stopped_on_its_rule)
            return {OutputState::Finished, "", n};
        if (one_range && held.first() == asked.first && held.end() < asked.end())
            return continuable("holds the samples " + held.format() + " of " + text(asked.first) + ":" + text(count));
        return different("holds the samples " + held.format() + ", " + text(asked.first) + ":" + text(count) + " asked",
                         n);
    }
    if (!one_range || held.first() != 0)
        return different("holds the samples " + held.format() + ", not a whole frame's from sample 0", n);
    const std::uint64_t target = r.spp.value_or(file.metadata.target_spp);
    if (n >= target || stopped_on_its_rule) return {OutputState::Finished, "", n};
    return continuable("holds " + text(n) + " of " + text(target) + " spp");
}

}  // namespace

OutputJudgement judge_output(const std::string& path, const RenderRequest& request, RenderCheck check) {
    const RenderStatus status = inspect_render(path, check);
    if (!status.exists) return {OutputState::Missing, "", 0};
    if (!status.readable || !status.summary) return different("unreadable (" + status.reason + ")", 0);
    const ExrFilmSummary& file = *status.summary;
    if (std::string why = mismatch(file, request); !why.empty()) return different(std::move(why), file.samples_per_pixel);
    return judge_samples(file, request);
}

const char* state_name(OutputState state) {
    switch (state) {
        case OutputState::Missing: return "missing";
        case OutputState::Finished: return "finished";
        case OutputState::Continuable: return "partial";
        case OutputState::Different: return "different";
    }
    return "?";
}

}  // namespace orb::exr
