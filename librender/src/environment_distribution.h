// Importance sampling of an environment map: a piecewise-constant 2D
// distribution over its latitude-longitude texels (docs/rendering.md,
// "Environment"). Built on the host, sampled by kernels/environment.cl from
// the tables EnvironmentCdf and EnvironmentTexel (device_types.h).
//
// A texel's weight is its radiance (the mean of R, G and B) times its solid
// angle, (2 pi / width) (cos theta_top - cos theta_bottom): sin theta
// integrated exactly over the row, so texels near the poles, which cover
// little of the sphere, are picked as rarely as they light anything. Within
// the chosen texel the direction is uniform in solid angle (uniform in phi
// and in cos theta), so the density is constant there: the texel's
// probability over its solid angle.
#pragma once

#include <cstddef>
#include <vector>

namespace orb::render {

struct EnvironmentDistribution {
    int width = 0;
    int height = 0;
    // The cumulative probabilities the device searches, as stored (float):
    // rows first, then each row's columns (the EnvironmentCdf layout).
    std::vector<float> cdf;
    // Each texel's probability as the float tables realise it (the product
    // of the differences of consecutive stored entries, in double), and its
    // solid-angle density: probability / solid angle. The kernel reports this
    // density for exactly the texels it picks, so sampling and pdf agree even
    // where a float cannot resolve a very dim texel's share (it gets 0 and is
    // never picked; multiple importance sampling then relies on the BSDF).
    std::vector<double> probability;
    std::vector<double> pdf;
    double total_weight = 0;  // sum of the weights; 0: nothing to sample
};

// Solid angle of one texel of row `row` of a width x height map.
double environment_texel_solid_angle(int row, int width, int height);

// `weights`: one non-negative weight per texel (row-major, row 0 at the top),
// before the solid-angle factor, e.g. the mean radiance. Throws
// std::invalid_argument for a size mismatch or an empty map.
EnvironmentDistribution build_environment_distribution(const std::vector<double>& weights, int width, int height);

// The texel the device's search picks for two uniform numbers in [0, 1)
// (the first chooses the row, the second the column), as row * width + column.
// The host twin of sample_environment_texel in kernels/environment.cl, for tests.
std::size_t sample_environment_texel(const EnvironmentDistribution& distribution, float u_row, float u_column);

}  // namespace orb::render
