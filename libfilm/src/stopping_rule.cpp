#include "orb/film/stopping_rule.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "orb/film/parallel_blocks.h"

namespace orb::film {

std::vector<std::uint32_t> pixels_still_sampling(const std::vector<double>& pixel_relmse, int width, int height,
                                                 double noise_threshold,
                                                 const std::vector<std::uint32_t>& candidates)
{
    const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (width <= 0 || height <= 0 || pixel_relmse.size() != pixels)
        throw std::invalid_argument("pixels_still_sampling: one error per pixel of the image");
    // Compared as relMSE: sqrt(e) >= t is e >= t^2 for t > 0.
    const double noisy_from = noise_threshold * noise_threshold;
    const auto noisy = [&](int x, int y) {
        return pixel_relmse[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] >=
               noisy_from;
    };
    // Candidates in blocks, each on a core, kept in their order: a decision
    // looks at every pixel still sampling, millions at 1920x1080.
    const auto keep_of = [&](std::size_t first, std::size_t end, std::vector<std::uint32_t>& kept) {
        for (std::size_t c = first; c < end; ++c) {
            const std::uint32_t pixel = candidates[c];
            const int x = static_cast<int>(pixel % static_cast<std::uint32_t>(width));
            const int y = static_cast<int>(pixel / static_cast<std::uint32_t>(width));
            bool keep = false;
            for (int dy = -1; dy <= 1 && !keep; ++dy)
                for (int dx = -1; dx <= 1 && !keep; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx >= 0 && ny >= 0 && nx < width && ny < height && noisy(nx, ny)) keep = true;
                }
            if (keep) kept.push_back(pixel);
        }
    };
    for (std::uint32_t pixel : candidates)
        if (pixel >= pixels) throw std::invalid_argument("pixels_still_sampling: a candidate outside the image");
    std::vector<std::vector<std::uint32_t>> kept_by_block(block_count(candidates.size()));
    for_each_block(candidates.size(), [&](std::size_t block, std::size_t first, std::size_t end) {
        keep_of(first, end, kept_by_block[block]);
    });
    std::vector<std::uint32_t> kept;
    for (const std::vector<std::uint32_t>& block : kept_by_block) kept.insert(kept.end(), block.begin(), block.end());
    return kept;
}

}  // namespace orb::film
