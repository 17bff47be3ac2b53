// A pass's samples split over devices so that the pass ends as early as it can.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "sample_split.h"

namespace orb::render {
namespace {

int sum(const std::vector<int>& shares) { return std::accumulate(shares.begin(), shares.end(), 0); }

// When the last share of a pass ends, each share taking n * seconds.
double pass_end(const std::vector<int>& shares, const std::vector<double>& seconds)
{
    double end = 0;
    for (std::size_t d = 0; d < shares.size(); ++d) end = std::max(end, shares[d] * seconds[d]);
    return end;
}

// The earliest end of any split, by trying them all (two or three devices).
double best_end_by_search(int count, const std::vector<double>& seconds)
{
    double best = std::numeric_limits<double>::infinity();
    for (int a = 0; a <= count; ++a) {
        if (seconds.size() == 2) {
            best = std::min(best, pass_end({a, count - a}, seconds));
            continue;
        }
        for (int b = 0; a + b <= count; ++b) best = std::min(best, pass_end({a, b, count - a - b}, seconds));
    }
    return best;
}

DeviceInfo device(bool gpu, unsigned compute_units)
{
    DeviceInfo info;
    info.is_gpu = gpu;
    info.is_cpu = !gpu;
    info.compute_units = compute_units;
    return info;
}

TEST(SampleSplit, OneDeviceTakesEverySample)
{
    for (int count : {0, 1, 7, 4096}) EXPECT_EQ(split_for_earliest_finish(count, {0.3}), (std::vector<int>{count}));
    EXPECT_EQ(split_pass(5, {DeviceSpeed{}}), (std::vector<int>{5}));
}

TEST(SampleSplit, EqualDevicesShareEvenlyWithTheRemainderToTheEarlierOnes)
{
    EXPECT_EQ(split_for_earliest_finish(12, {2.0, 2.0}), (std::vector<int>{6, 6}));
    EXPECT_EQ(split_for_earliest_finish(10, {1.0, 1.0, 1.0}), (std::vector<int>{4, 3, 3}));
    EXPECT_EQ(split_for_earliest_finish(5, {1.0, 1.0}), (std::vector<int>{3, 2}));
}

TEST(SampleSplit, FewerSamplesThanDevicesGoToTheFastest)
{
    EXPECT_EQ(split_for_earliest_finish(1, {1.0, 1.0}), (std::vector<int>{1, 0}));
    EXPECT_EQ(split_for_earliest_finish(2, {1.0, 1.0, 1.0}), (std::vector<int>{1, 1, 0}));
    // Both splits of two samples below end at 2: the faster device takes them.
    EXPECT_EQ(split_for_earliest_finish(2, {3.0, 1.0, 2.0}), (std::vector<int>{0, 2, 0}));
    EXPECT_EQ(split_for_earliest_finish(2, {3.0, 1.0, 1.5}), (std::vector<int>{0, 1, 1}));
    EXPECT_EQ(split_for_earliest_finish(0, {3.0, 1.0}), (std::vector<int>{0, 0}));
}

// A CPU next to a GPU 50 times faster: in a pass the GPU ends in less time
// than the CPU takes for one sample, the CPU gets nothing (it would hold the
// pass up); in a longer one it gets the samples it ends in time.
TEST(SampleSplit, ADeviceFiftyTimesSlowerGetsSamplesOnlyWhenItEndsInTime)
{
    const std::vector<double> gpu_and_cpu{1.0, 50.0};
    EXPECT_EQ(split_for_earliest_finish(1, gpu_and_cpu), (std::vector<int>{1, 0}));
    EXPECT_EQ(split_for_earliest_finish(30, gpu_and_cpu), (std::vector<int>{30, 0}));
    // 50 on the GPU end when one CPU sample does: a tie, so the GPU keeps it.
    EXPECT_EQ(split_for_earliest_finish(50, gpu_and_cpu), (std::vector<int>{50, 0}));
    EXPECT_EQ(split_for_earliest_finish(51, gpu_and_cpu), (std::vector<int>{50, 1}));
    EXPECT_EQ(split_for_earliest_finish(100, gpu_and_cpu), (std::vector<int>{99, 1}));
    EXPECT_EQ(split_for_earliest_finish(102, {50.0, 1.0}), (std::vector<int>{2, 100}));  // order does not matter
}

// Whatever the speeds, the shares add up to the count and the pass ends as
// early as the best of all splits.
TEST(SampleSplit, TheSplitEndsAsEarlyAsAnySplitAndAddsUp)
{
    const std::vector<std::vector<double>> speeds{{0.3, 0.7},       {1e-9, 1.0},      {1.0, 1e9},
                                                  {2.0, 3.0, 5.0},  {1.0, 1.0, 1.0},  {0.04, 0.001, 0.0008},
                                                  {7.0, 7.0, 0.1},  {1.0, 1.0 + 1e-12}};
    for (const std::vector<double>& seconds : speeds)
        for (int count : {1, 2, 3, 5, 17, 99, 250}) {
            const std::vector<int> shares = split_for_earliest_finish(count, seconds);
            ASSERT_EQ(sum(shares), count);
            EXPECT_DOUBLE_EQ(pass_end(shares, seconds), best_end_by_search(count, seconds))
                << count << " samples, " << seconds.size() << " devices, first " << seconds[0];
            for (int share : shares) EXPECT_GE(share, 0);
        }
}

TEST(SampleSplit, LargeCountsRoundToWholeSamplesThatAddUp)
{
    const int most = std::numeric_limits<int>::max();
    const std::vector<int> shares = split_for_earliest_finish(most, {1.0, 2.0, 4.0});
    EXPECT_EQ(static_cast<long long>(shares[0]) + shares[1] + shares[2], most);
    EXPECT_NEAR(shares[0], most * 4.0 / 7.0, 4.0);
    EXPECT_NEAR(shares[1], most * 2.0 / 7.0, 4.0);
    EXPECT_EQ(split_for_earliest_finish(4096, {1.0, 3.0}), (std::vector<int>{3072, 1024}));
    EXPECT_EQ(split_for_earliest_finish(7, {1.0, 2.0}), (std::vector<int>{5, 2}));  // ends at 5 (4 and 3: 6)
}

TEST(SampleSplit, UntimedDevicesAreJudgedByTheirPriorAgainstTheTimedOnes)
{
    // Nobody timed: the priors alone (only their ratio matters).
    EXPECT_EQ(expected_seconds_per_sample({{0, 2.0}, {0, 4.0}}), (std::vector<double>{0.5, 0.25}));
    EXPECT_EQ(split_pass(9, {{0, 1.0}, {0, 2.0}}), (std::vector<int>{3, 6}));
    EXPECT_EQ(split_pass(10, {{0, 1.0}, {0, 1.0}, {0, 1.0}}), (std::vector<int>{4, 3, 3}));
    // A device timed at 0.01 s with prior 100: an untimed one of prior 1 is
    // expected to take 1 s, one of prior 50 0.02 s.
    EXPECT_EQ(expected_seconds_per_sample({{0.01, 100.0}, {0, 1.0}, {0, 50.0}}),
              (std::vector<double>{0.01, 1.0, 0.02}));
    // Measured values win over the priors.
    EXPECT_EQ(expected_seconds_per_sample({{0.01, 100.0}, {0.02, 1.0}}), (std::vector<double>{0.01, 0.02}));
}

// Before anything has been timed, a 16-thread CPU next to an H100 (132
// compute units) is expected to be far slower: a first pass of a few
// samples goes to the GPU alone, as does a whole GPU pass at 1080p.
TEST(SampleSplit, PriorsRateGpusAboveCpusOfAsManyUnits)
{
    const DeviceInfo h100 = device(true, 132), xeon = device(false, 16);
    EXPECT_EQ(prior_speed(xeon), 16.0);
    EXPECT_EQ(prior_speed(h100), 132.0 * kGpuUnitAsCpuUnits);
    EXPECT_GT(prior_speed(device(true, 1)), prior_speed(device(false, 1)));
    EXPECT_EQ(prior_speed(device(false, 0)), 1.0);  // a device that reports no units counts as one
    const std::vector<DeviceSpeed> untimed{{0, prior_speed(xeon)}, {0, prior_speed(h100)}};
    EXPECT_EQ(split_pass(2, untimed), (std::vector<int>{0, 2}));
    EXPECT_EQ(split_pass(64, untimed), (std::vector<int>{0, 64}));
    // Once the GPU is timed, the CPU is still judged by the ratio of the priors.
    EXPECT_EQ(split_pass(64, {{0, prior_speed(xeon)}, {0.0008, prior_speed(h100)}}), (std::vector<int>{0, 64}));
    // Once timed at 50x slower, it could end a pass of 64 one sample sooner
    // (1.6%): not worth what taking part costs.
    EXPECT_EQ(split_pass(64, {{0.04, prior_speed(xeon)}, {0.0008, prior_speed(h100)}}), (std::vector<int>{0, 64}));
}

// A device is used only where it ends the pass kLeastWorthwhileGain sooner
// than the others would alone.
TEST(SampleSplit, ADeviceThatGainsTooLittleIsLeftOut)
{
    EXPECT_EQ(split_over_worthwhile_devices(100, {1.0, 50.0}), (std::vector<int>{100, 0}));
    EXPECT_EQ(split_over_worthwhile_devices(4096, {1.0, 50.0}), (std::vector<int>{4096, 0}));
    EXPECT_EQ(split_over_worthwhile_devices(100, {1.0, 10.0}), (std::vector<int>{91, 9}));  // ends at 91, not 100
    // The edge: a device 19 times slower is 5.3% of the speed, one 21 times slower 4.8%.
    EXPECT_EQ(split_over_worthwhile_devices(1000, {1.0, 19.0}), (std::vector<int>{950, 50}));
    EXPECT_EQ(split_over_worthwhile_devices(1000, {1.0, 21.0}), (std::vector<int>{1000, 0}));
    // Two GPUs and a slow CPU: the CPU alone stays out.
    EXPECT_EQ(split_over_worthwhile_devices(100, {1.0, 1.0, 50.0}), (std::vector<int>{50, 50, 0}));
    EXPECT_EQ(split_over_worthwhile_devices(100, {50.0, 1.0, 1.0}), (std::vector<int>{0, 50, 50}));
    // Equal devices always share.
    EXPECT_EQ(split_over_worthwhile_devices(2, {1.0, 1.0}), (std::vector<int>{1, 1}));
    EXPECT_EQ(split_over_worthwhile_devices(1, {1.0, 1.0}), (std::vector<int>{1, 0}));
    EXPECT_EQ(split_over_worthwhile_devices(7, {1.0}), (std::vector<int>{7}));
    EXPECT_EQ(split_over_worthwhile_devices(0, {1.0, 2.0}), (std::vector<int>{0, 0}));
    // Whatever is left out, the shares add up and end no later than the
    // earliest split by more than the margin.
    for (const std::vector<double>& seconds : std::vector<std::vector<double>>{
             {0.3, 0.7}, {1.0, 30.0, 2.0}, {0.04, 0.001, 0.0008}, {7.0, 7.0, 0.1}})
        for (int count : {1, 3, 17, 250}) {
            const std::vector<int> shares = split_over_worthwhile_devices(count, seconds);
            ASSERT_EQ(sum(shares), count);
            EXPECT_LE(pass_end(shares, seconds),
                      pass_end(split_for_earliest_finish(count, seconds), seconds) * (1.0 + kLeastWorthwhileGain));
        }
}

TEST(SampleSplit, RefusesWhatItCannotSplit)
{
    EXPECT_THROW(split_for_earliest_finish(4, {}), std::invalid_argument);
    EXPECT_THROW(split_for_earliest_finish(4, {1.0, 0.0}), std::invalid_argument);
    EXPECT_THROW(split_for_earliest_finish(4, {1.0, std::numeric_limits<double>::infinity()}), std::invalid_argument);
    EXPECT_THROW(split_for_earliest_finish(-1, {1.0}), std::invalid_argument);
    EXPECT_THROW(split_pass(4, {}), std::invalid_argument);
    EXPECT_THROW(split_pass(4, {{0, 0.0}}), std::invalid_argument);
    EXPECT_THROW(split_pass(4, {{-1.0, 1.0}}), std::invalid_argument);
}

}  // namespace
}  // namespace orb::render
