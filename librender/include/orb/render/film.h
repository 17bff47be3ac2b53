// The film: per-pixel sums over samples plus the number of samples in each
// pixel. Keeping sums (not means) makes passes, resumed runs and sample
// slices rendered on other machines merge exactly by addition.
#pragma once

#include <cstdint>
#include <vector>

namespace orb::render {

struct Film {
    int width = 0;
    int height = 0;
    std::uint64_t samples_per_pixel = 0;  // every pixel holds the same count

    // Row-major, top row first. RGB/XYZ sets hold 3 floats per pixel.
    std::vector<float> radiance;     // sum of L (beauty)
    std::vector<float> radiance_sq;  // sum of L^2, per channel, for the variance of the mean
    std::vector<float> direct;       // sum of light arriving by one scattering event from an emitter
    std::vector<float> indirect;     // sum of light scattered two or more times
    std::vector<float> emission;     // sum of emission seen directly (through specular chains)
    std::vector<float> albedo;       // sum of the first non-specular hit's reflectance
    std::vector<float> normal;       // sum of the world normal at the first hit (0 for misses)
    std::vector<float> alpha;        // 1 float per pixel: sum of coverage (1 hit, 0 miss)
    // Not sums: taken from the ray through the pixel centre.
    std::vector<float> depth;        // distance along the camera ray to the first hit, +inf for a miss
    std::vector<float> object_id;    // index of the sphere at the first hit, -1 for none

    void resize(int w, int h);       // zero sums, depth=+inf, id=-1, samples=0
    std::size_t pixel_count() const { return static_cast<std::size_t>(width) * height; }

    // Adds another film's sums and counts (same size; depth/id taken from `other` if this is empty).
    void accumulate(const Film& other);
};

}  // namespace orb::render
