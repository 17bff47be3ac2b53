#include "exr_header_attributes.h"

#include <climits>
#include <stdexcept>

#include "exr_attributes.h"

namespace orb::exr::detail {
namespace {

int checked_int(long long value, const char* what) {
    if (value < INT_MIN || value > INT_MAX) throw std::invalid_argument(std::string(what) + " does not fit the EXR int attribute");
    return static_cast<int>(value);
}

int checked_count(std::uint64_t value, const char* what) {
    if (value > static_cast<std::uint64_t>(INT_MAX))
        throw std::invalid_argument(std::string(what) + " does not fit the EXR int attribute");
    return static_cast<int>(value);
}

}  // namespace

std::vector<HeaderAttribute> header_attributes(const Film& film, const ExrMetadata& m,
                                               const ExrWriteOptions& options) {
    std::vector<HeaderAttribute> a{
        {attr::kFilmFormat, kFilmFormatVersion},
        {attr::kSpp, checked_count(film.samples_per_pixel, attr::kSpp)},
        {attr::kSampleRanges, film.held_ranges().format()},
        {attr::kTargetSpp, checked_count(m.target_spp, attr::kTargetSpp)},
        {attr::kSeed, std::to_string(m.seed)},  // 64 bits do not fit an EXR int
        {attr::kMaxDepth, m.max_depth},
        {attr::kMode, m.mode},
        {attr::kSampler, m.sampler},
        {attr::kDevice, m.device},
        {attr::kRenderSeconds, m.render_seconds},
        {attr::kSceneFile, m.scene_file},
        {attr::kSceneHash, m.scene_hash},
        {attr::kSceneTime, m.scene_time},
        {attr::kVersion, m.version},
        {attr::kPasses, format_passes(options.passes)},
        {attr::kEnvironmentSeen, m.environment_seen ? 1 : 0},
    };
    if (m.frame) {
        a.push_back({attr::kFrame, checked_int(m.frame->number, attr::kFrame)});
        a.push_back({attr::kFps, m.frame->fps});
    }
    if (m.noise_threshold) a.push_back({attr::kNoiseThreshold, *m.noise_threshold});
    if (m.target_error) a.push_back({attr::kTargetError, *m.target_error});
    if (m.adaptive_stop) a.push_back({attr::kAdaptiveStop, std::string(adaptive_stop_name(*m.adaptive_stop))});
    if (options.exact_sums) a.push_back({attr::kExactSums, kExactSumsEncoding});
    if (!m.kernel.empty()) a.push_back({attr::kKernel, m.kernel});
    // OpenEXR's standard names and types (ImfStandardAttributes.h).
    a.push_back({"worldToCamera", m.world_to_camera});
    a.push_back({"worldToNDC", m.world_to_ndc});
    return a;
}

}  // namespace orb::exr::detail
