#include "orb/job/film_progress.h"

#include <algorithm>
#include <limits>

namespace orb::job {

ProgressEstimate estimate_progress(const render::ProgressState& s, double pixels, double time_limit) {
    const double spp_per_second = pixels > 0 ? s.samples_per_second / pixels : 0;
    ProgressEstimate estimate;
    estimate.eta_seconds = spp_per_second > 0 ? double(s.target_spp - std::min(s.spp, s.target_spp)) / spp_per_second
                                              : std::numeric_limits<double>::infinity();
    if (time_limit > 0) estimate.eta_seconds = std::min(estimate.eta_seconds, std::max(0.0, time_limit - s.elapsed_seconds));
    estimate.fraction = s.target_spp ? std::min(1.0, double(s.spp) / double(s.target_spp)) : 1.0;
    return estimate;
}

}  // namespace orb::job
