// Splitting a pass's samples over devices so that the pass ends as early as
// the devices' speeds allow.
#pragma once

#include <vector>

#include "orb/render/device.h"

namespace orb::render {

// What the split knows of a device's speed.
struct DeviceSpeed {
    double seconds_per_sample = 0;  // measured, per sample per pixel; 0: not timed yet
    double prior_speed = 1;         // prior_speed() of the device (> 0), for while it is not timed
};

// A guess of a device's speed before it has rendered anything, in CPU
// compute units (hardware threads): a CPU's compute units, or a GPU's times
// kGpuUnitAsCpuUnits. Only ratios between devices matter.
double prior_speed(const DeviceInfo& device);

// What one GPU compute unit is taken to be worth in CPU compute units. An
// H100's SM did the work of about 6 threads of a 16-core Xeon (the two
// measured 50x apart on the Cornell box), and integrated GPUs' units are
// weaker still, so 16 overrates GPUs on purpose: a CPU thought slower than it
// is only misses a chance to help, one thought faster holds up every pass
// until it has been timed.
inline constexpr double kGpuUnitAsCpuUnits = 16.0;

// Each device's expected seconds per sample: its measured value, or for one
// not yet timed its prior relative to the timed devices' (the mean of their
// seconds per sample times their prior speed, over its prior speed); 1 /
// prior speed when no device has been timed (only the ratios matter).
// Throws std::invalid_argument for no devices, a non-positive prior or a
// negative or non-finite measurement.
std::vector<double> expected_seconds_per_sample(const std::vector<DeviceSpeed>& devices);

// Whole samples for each device out of `count` (>= 0), for a pass that ends
// when the last device's share does (device d's share of n samples takes
// n * seconds_per_sample[d]): the allocation whose expected end is the
// earliest. Samples go one at a time to the device whose share would then
// end first (on a tie, the faster device, then the earlier one), so a device
// gets samples only when doing them ends no later than the pass would end
// without it; a slow device gets none in a pass too short for it. Throws
// std::invalid_argument for a negative count, no devices or a non-positive
// or non-finite time.
std::vector<int> split_for_earliest_finish(int count, const std::vector<double>& seconds_per_sample);

// How much sooner a device must end a pass to be given part of it. Taking
// part costs what the times above leave out: a launch and a waiting thread
// each pass, on a CPU the cores the GPUs' drivers also need, and for every
// image one more film read back and added (at 1920x1080 on the H100's
// machine, 6 ms for its CPU's film reused, about 100 ms fresh, where that
// CPU taking 1 sample in 64 saves the GPU under 1 ms a pass).
inline constexpr double kLeastWorthwhileGain = 0.05;

// split_for_earliest_finish() over the devices worth using: while leaving
// one out would end the pass less than kLeastWorthwhileGain later than with
// it, the one whose absence costs least is left out (it gets 0). Two equal
// devices both take part; a device 20 or more times slower than the others
// together does not, however long the pass.
std::vector<int> split_over_worthwhile_devices(int count, const std::vector<double>& seconds_per_sample);

// The shares of a pass of `count` samples over `devices`: the split above
// with their expected_seconds_per_sample().
std::vector<int> split_pass(int count, const std::vector<DeviceSpeed>& devices);

}  // namespace orb::render
