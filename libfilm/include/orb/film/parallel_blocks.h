// Per-pixel work on every core of the host: a decision of adaptive
// sampling looks at millions of pixels, which on one core took as long as
// tens of a GPU's passes; a denoiser's inputs are as many.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>

namespace orb::film {

inline constexpr std::size_t kParallelBlock = 1 << 16;

// The number of blocks for_each_block splits `count` items into.
constexpr std::size_t block_count(std::size_t count) { return (count + kParallelBlock - 1) / kParallelBlock; }

namespace detail {
// Calls body(b) once for each b in [0, blocks) on the calling thread and the
// process's kept workers, one per further core (libfilm/src/parallel_blocks.cpp);
// returns when all are done.
void run_blocks(std::size_t blocks, const std::function<void(std::size_t)>& body);
}  // namespace detail

// Calls body(block, first, end) once for each block [first, end) of
// [0, count), the blocks shared among the host's cores; returns when all are
// done. A body that writes only its own block's results needs no lock. The
// body must not throw (as on a thread of its own, an escaping exception ends
// the process).
template <class Body>
void for_each_block(std::size_t count, const Body& body)
{
    const std::size_t blocks = block_count(count);
    if (blocks <= 1) {
        if (count) body(std::size_t{0}, std::size_t{0}, count);
        return;
    }
    detail::run_blocks(blocks, [&](std::size_t b) {
        body(b, b * kParallelBlock, std::min(count, (b + 1) * kParallelBlock));
    });
}

}  // namespace orb::film
