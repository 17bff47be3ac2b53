// The threads that fill and compress EXR blocks, shared by every encode in
// the process (libexr/src/block_workers.h): each block runs once, from
// several encodes at once, and a failing block's error reaches its encode.
#include "block_workers.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

namespace {

using orb::exr::detail::run_blocks;

TEST(BlockWorkers, EachBlockRunsOnceWhileSeveralEncodesShareTheWorkers) {
    constexpr int kEncodes = 4, kBlocks = 2000;
    std::vector<std::vector<std::atomic<int>>> runs(kEncodes);
    for (auto& encode : runs) encode = std::vector<std::atomic<int>>(kBlocks);
    std::vector<std::thread> encodes;
    for (int e = 0; e < kEncodes; ++e)
        encodes.emplace_back([&, e] { run_blocks(kBlocks, [&](int block) { ++runs[e][block]; }); });
    for (std::thread& encode : encodes) encode.join();
    for (int e = 0; e < kEncodes; ++e)
        for (int block = 0; block < kBlocks; ++block) ASSERT_EQ(runs[e][block].load(), 1) << e << " " << block;
}

TEST(BlockWorkers, AFailingBlockStopsItsEncodeWithItsErrorAndTheWorkersGoOn) {
    constexpr int kBlocks = 100000;
    std::atomic<int> ran{0};
    try {
        run_blocks(kBlocks, [&](int block) {
            ++ran;
            if (block == 0) throw std::runtime_error("block 0 failed");
        });
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "block 0 failed");
    }
    EXPECT_LT(ran.load(), kBlocks);  // the blocks after the error were not started
    std::atomic<int> after{0};
    run_blocks(100, [&](int) { ++after; });
    EXPECT_EQ(after.load(), 100);
    run_blocks(0, [&](int) { ++after; });
    EXPECT_EQ(after.load(), 100);
}

}  // namespace
