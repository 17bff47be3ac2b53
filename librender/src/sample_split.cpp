#include "sample_split.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace orb::render {
namespace {

void check_speeds(const std::vector<DeviceSpeed>& devices)
{
    if (devices.empty()) throw std::invalid_argument("no devices to split samples over");
    for (const DeviceSpeed& device : devices) {
        if (!(device.prior_speed > 0) || !std::isfinite(device.prior_speed))
            throw std::invalid_argument("a device's prior speed must be positive");
        if (!(device.seconds_per_sample >= 0) || !std::isfinite(device.seconds_per_sample))
            throw std::invalid_argument("a device's measured seconds per sample must be finite and not negative");
    }
}

// The times relative to the fastest device's, so that the split's sums stay
// in range whatever the units.
std::vector<double> relative_times(const std::vector<double>& seconds_per_sample)
{
    if (seconds_per_sample.empty()) throw std::invalid_argument("no devices to split samples over");
    for (double s : seconds_per_sample)
        if (!(s > 0) || !std::isfinite(s)) throw std::invalid_argument("device seconds per sample must be positive");
    const double fastest = *std::min_element(seconds_per_sample.begin(), seconds_per_sample.end());
    std::vector<double> times;
    for (double s : seconds_per_sample) times.push_back(s / fastest);
    return times;
}

// What each device surely gets in the earliest-ending split: the samples its
// share finishes by the end the pass would have if samples could be cut into
// fractions, taken a hair early so that float rounding never gives a device
// a sample the whole-sample split would not.
std::vector<int> shares_by_fractional_end(int count, const std::vector<double>& times)
{
    double samples_per_time = 0;
    for (double t : times) samples_per_time += 1.0 / t;
    const double end = count / samples_per_time * (1.0 - 1e-9);
    std::vector<int> shares;
    int given = 0;
    for (double t : times) {
        shares.push_back(static_cast<int>(std::min<double>(count - given, std::floor(end / t))));
        given += shares.back();
    }
    return shares;
}

// The device whose share would end first with one more sample: ties go to
// the faster device, then to the earlier one.
std::size_t next_to_take(const std::vector<int>& shares, const std::vector<double>& times)
{
    std::size_t best = 0;
    for (std::size_t d = 1; d < shares.size(); ++d) {
        const double end = (shares[d] + 1.0) * times[d];
        const double best_end = (shares[best] + 1.0) * times[best];
        if (end < best_end || (end == best_end && times[d] < times[best])) best = d;
    }
    return best;
}

double pass_end(const std::vector<int>& shares, const std::vector<double>& seconds_per_sample)
{
    double end = 0;
    for (std::size_t d = 0; d < shares.size(); ++d) end = std::max(end, shares[d] * seconds_per_sample[d]);
    return end;
}

// The earliest-ending split over the devices still `used`; the others get 0.
std::vector<int> split_among(int count, const std::vector<double>& seconds_per_sample, const std::vector<bool>& used)
{
    std::vector<double> times;
    for (std::size_t d = 0; d < used.size(); ++d)
        if (used[d]) times.push_back(seconds_per_sample[d]);
    const std::vector<int> used_shares = split_for_earliest_finish(count, times);
    std::vector<int> shares(used.size(), 0);
    for (std::size_t d = 0, u = 0; d < used.size(); ++d)
        if (used[d]) shares[d] = used_shares[u++];
    return shares;
}

// The device with samples whose absence would lengthen the pass least, and
// the pass's end without it; none (shares.size()) when only one has samples.
std::pair<std::size_t, double> least_needed(int count, const std::vector<double>& seconds_per_sample,
                                            const std::vector<bool>& used, const std::vector<int>& shares)
{
    std::pair<std::size_t, double> least{shares.size(), 0.0};
    if (std::count_if(shares.begin(), shares.end(), [](int share) { return share > 0; }) < 2) return least;
    for (std::size_t d = 0; d < shares.size(); ++d) {
        if (shares[d] == 0) continue;
        std::vector<bool> without = used;
        without[d] = false;
        const double end = pass_end(split_among(count, seconds_per_sample, without), seconds_per_sample);
        if (least.first == shares.size() || end < least.second) least = {d, end};
    }
    return least;
}

int total(const std::vector<int>& shares)
{
    long long sum = 0;
    for (int share : shares) sum += share;
    return static_cast<int>(sum);
}

}  // namespace

double prior_speed(const DeviceInfo& device)
{
    const double units = std::max(1u, device.compute_units);
    return device.is_gpu ? units * kGpuUnitAsCpuUnits : units;
}

std::vector<double> expected_seconds_per_sample(const std::vector<DeviceSpeed>& devices)
{
    check_speeds(devices);
    // Seconds per sample of a device of prior speed 1, as the timed devices tell it.
    double unit_seconds = 0;
    int timed = 0;
    for (const DeviceSpeed& device : devices)
        if (device.seconds_per_sample > 0) {
            unit_seconds += device.seconds_per_sample * device.prior_speed;
            ++timed;
        }
    unit_seconds = timed > 0 ? unit_seconds / timed : 1.0;
    std::vector<double> seconds;
    for (const DeviceSpeed& device : devices)
        seconds.push_back(device.seconds_per_sample > 0 ? device.seconds_per_sample
                                                        : unit_seconds / device.prior_speed);
    return seconds;
}

std::vector<int> split_for_earliest_finish(int count, const std::vector<double>& seconds_per_sample)
{
    if (count < 0) throw std::invalid_argument("a pass cannot split a negative number of samples");
    const std::vector<double> times = relative_times(seconds_per_sample);
    // Taking the samples in the order in which they would end, as
    // next_to_take does, gives the earliest end there is: the pass's
    // count-th earliest sample end over all devices.
    std::vector<int> shares = shares_by_fractional_end(count, times);
    for (int given = total(shares); given < count; ++given) shares[next_to_take(shares, times)] += 1;
    return shares;
}

std::vector<int> split_over_worthwhile_devices(int count, const std::vector<double>& seconds_per_sample)
{
    std::vector<bool> used(seconds_per_sample.size(), true);
    std::vector<int> shares = split_for_earliest_finish(count, seconds_per_sample);
    for (;;) {
        const auto [device, end_without] = least_needed(count, seconds_per_sample, used, shares);
        if (device == shares.size()) return shares;
        if (end_without > pass_end(shares, seconds_per_sample) * (1.0 + kLeastWorthwhileGain)) return shares;
        used[device] = false;
        shares = split_among(count, seconds_per_sample, used);
    }
}

std::vector<int> split_pass(int count, const std::vector<DeviceSpeed>& devices)
{
    return split_over_worthwhile_devices(count, expected_seconds_per_sample(devices));
}

}  // namespace orb::render
