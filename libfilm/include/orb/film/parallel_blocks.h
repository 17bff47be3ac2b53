// Per-pixel work on every core of the host: a decision of adaptive
// sampling looks at millions of pixels, which on one core took as long as
// tens of a GPU's passes; a denoiser's inputs are as many.
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace orb::film {

inline constexpr std::size_t kParallelBlock = 1 << 16;

// The number of blocks for_each_block splits `count` items into.
constexpr std::size_t block_count(std::size_t count) { return (count + kParallelBlock - 1) / kParallelBlock; }

// Calls body(block, first, end) once for each block [first, end) of
// [0, count), the blocks shared among the host's cores; returns when all are
// done. A body that writes only its own block's results needs no lock.
template <class Body>
void for_each_block(std::size_t count, const Body& body)
{
    const std::size_t blocks = block_count(count);
    const std::size_t workers =
        std::max<std::size_t>(1, std::min<std::size_t>(blocks, std::max(1u, std::thread::hardware_concurrency())));
    const auto work = [&](std::size_t first_block) {
        for (std::size_t b = first_block; b < blocks; b += workers)
            body(b, b * kParallelBlock, std::min(count, (b + 1) * kParallelBlock));
    };
    std::vector<std::thread> threads;
    for (std::size_t w = 1; w < workers; ++w) threads.emplace_back(work, w);
    work(0);
    for (std::thread& t : threads) t.join();
}

}  // namespace orb::film
