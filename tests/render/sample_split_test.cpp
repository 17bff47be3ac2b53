// A pass's samples split over devices in proportion to their speed.
#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>

#include "sample_split.h"

namespace orb::render {
namespace {

int sum(const std::vector<int>& shares) { return std::accumulate(shares.begin(), shares.end(), 0); }

TEST(SampleSplit, SharesFollowTheWeightsAndAddUp)
{
    EXPECT_EQ(split_in_proportion(12, {1.0, 2.0}), (std::vector<int>{4, 8}));
    EXPECT_EQ(split_in_proportion(10, {1.0, 1.0, 1.0}), (std::vector<int>{4, 3, 3}));  // ties: earlier first
    EXPECT_EQ(split_in_proportion(1, {1.0, 1.0}), (std::vector<int>{1, 0}));
    EXPECT_EQ(split_in_proportion(0, {3.0, 1.0}), (std::vector<int>{0, 0}));
    EXPECT_EQ(split_in_proportion(7, {5.0}), (std::vector<int>{7}));
    for (int count : {1, 5, 99, 1000, 4096})
        for (const std::vector<double>& weights :
             std::vector<std::vector<double>>{{0.3, 0.7}, {1e-9, 1.0}, {2.0, 3.0, 5.0}, {1.0, 1.0, 1.0, 1.0}}) {
            const std::vector<int> shares = split_in_proportion(count, weights);
            ASSERT_EQ(sum(shares), count);
            double total = 0;
            for (double w : weights) total += w;
            for (std::size_t d = 0; d < weights.size(); ++d)
                EXPECT_LT(std::abs(shares[d] - count * weights[d] / total), 1.0) << count << " share " << d;
        }
}

TEST(SampleSplit, NeedsPositiveWeights)
{
    EXPECT_THROW(split_in_proportion(4, {}), std::invalid_argument);
    EXPECT_THROW(split_in_proportion(4, {1.0, 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace orb::render
