#include "pass_tuner.h"

#include <algorithm>
#include <cmath>

namespace orb::render {
namespace {

// The first pass is a single sample: it shows an image early and measures
// the device. Growth is capped per pass so that one slow measurement (the
// first pass also pays for the driver's lazy compilation) cannot overshoot.
constexpr int kFirstPass = 1;
constexpr int kMaxGrowth = 4;
constexpr int kMaxSamples = 4096;

}  // namespace

void PassTuner::record(int samples, double seconds)
{
    if (samples <= 0 || !(seconds > 0.0)) return;
    const double per_sample = seconds / samples;
    ++passes_;
    last_samples_ = samples;
    // The first pass includes one-off costs, so later passes replace it outright.
    if (passes_ <= 2)
        seconds_per_sample_ = per_sample;
    else
        seconds_per_sample_ = 0.5 * seconds_per_sample_ + 0.5 * per_sample;
}

int PassTuner::suggested() const
{
    if (passes_ == 0 || !(seconds_per_sample_ > 0.0)) return kFirstPass;
    const double fitting = std::floor(target_seconds_ / seconds_per_sample_);
    const double capped = std::min({fitting, static_cast<double>(last_samples_) * kMaxGrowth,
                                    static_cast<double>(kMaxSamples)});
    return std::max(1, static_cast<int>(capped));
}

}  // namespace orb::render
