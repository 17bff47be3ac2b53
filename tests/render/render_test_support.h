// Helpers shared by the renderer tests: small hand-built scenes, rendering
// in given pass splits, and statistics from the film's own sums.
#pragma once

#include <string>
#include <vector>

#include "orb/tables/kernel_features.h"
#include "orb/render/renderer.h"
#include "orb/scene/scene.h"

namespace orb::render::test {

// Adds a material and returns its index.
std::uint32_t add_material(Scene& scene, MaterialType type, Vec3 color, Vec3 emission = {0, 0, 0}, double ior = 1.5);
// Adds a sphere and returns its index.
int add_sphere(Scene& scene, Vec3 centre, double radius, std::uint32_t material);

// Diffuse, mirror and glass balls on a huge floor, three lights of unequal
// power (the alias table picks them), seen through a thin lens: every branch
// of the path tracer's kernels (simd_kernel_test.cpp).
Scene every_branch_scene();

RenderConfig small_config(int width, int height, std::uint64_t seed = 7, int max_depth = 6,
                          IntegratorMode mode = IntegratorMode::Global);

// Renders `passes` (samples per pass, in order) with a fresh renderer.
Film render(const Scene& scene, const RenderConfig& config, const std::vector<int>& passes);

// The same with `cl_options` appended to the kernels' build options (the
// development knob ORB_CL_OPTIONS, for this render only; nullptr: none),
// to compare a program with a variant of it.
Film render_with_cl_options(const Scene& scene, const RenderConfig& config, const std::vector<int>& passes,
                            const char* cl_options);

// The features of a GPU's traversal for `scene` (choose_traversal on a GPU
// that is not NVIDIA's), with ORB_WARP_VOTE `warp_vote` (2: every lane votes
// yes, the speculative traversal run lane by lane), to run it on PoCL:
// through render_with_cl_options, the knob takes the features that differ
// from the defaults (device::kernel_feature_options).
device::KernelFeatures gpu_traversal(const Scene& scene, int warp_vote = 0);

// The same with the CPU kernel's lanes chosen (the development knob
// ORB_SIMD_LANES): "0" renders one path per work-item (ORB_LANES=1, as on
// GPUs), "4", "8" or "16" that many per work-item; nullptr: the device's
// default.
Film render_with_simd_lanes(const Scene& scene, const RenderConfig& config, const std::vector<int>& passes,
                            const char* lanes);

Scene load_scene_file(const std::string& path);  // .scn

// Mean over the chosen pixels of each pixel's mean radiance in channel c,
// and the standard error of that mean from the per-pixel variances that
// radiance_sq gives (pixels are independent; each pixel's variance of the
// mean is the unbiased sample variance over n).
struct PixelStatistics {
    double mean = 0;
    double standard_error = 0;
    std::size_t pixels = 0;
};
PixelStatistics radiance_statistics(const Film& film, const std::vector<std::size_t>& pixels, int channel);

// Pixels whose centre ray hit sphere `id`, together with all 8 neighbours
// (so no sample of the pixel can have seen anything else).
std::vector<std::size_t> interior_pixels_of(const Film& film, int id);

std::vector<std::size_t> all_pixels(const Film& film);

// The values a Sum channel's sums stand for (sum times its unit), in double.
std::vector<double> sum_values(const Film& film, film::Channel channel);

// A channel's storage, sums or values, as bytes (to compare any channel).
std::vector<std::byte> channel_bytes(const Film& film, film::Channel channel);

// Every entry of a channel set to `value`: units for a sum, the float for a value.
void fill_channel(Film& film, film::Channel channel, double value);

// Whether every entry of a channel is at its clear value (a sum at 0).
bool channel_is_clear(const Film& film, film::Channel channel);

// Every channel of two films of the same samples, bit for bit: the film's
// integer sums make any grouping of the samples (passes, slices, resumed
// runs, devices, adaptive decisions on the host or the device) the same.
void expect_same_films(const Film& a, const Film& b);

// Two films whose samples are the same paths computed by programs whose
// float arithmetic may round differently (lane widths, per-sphere colour
// tables): each sample's value may differ in its last float bits and then
// round to another unit, so the sums may differ by about n * 2^-24 of the
// sum of the magnitudes plus n units. For non-negative sums that is the sum
// itself; normals' components cancel, so their bound is n. The centre-ray
// channels exactly.
void expect_same_films_up_to_rounding(const Film& a, const Film& b);

// Two kernels that render the same paths of the same samples (render_pass
// at two lane widths): only where float
// rounding differs (fused multiply-adds, a reciprocal square root for a
// normalize) can a path take another branch near an edge or a roulette
// threshold. Expects at most a tenth of the values `a` and `b` (sums of a
// channel) apart by more than the same path's rounding, and the mean
// difference within 4 standard errors of the paired differences (no bias
// between the kernels).
void expect_mostly_same_paths(const std::vector<double>& a, const std::vector<double>& b, const std::string& what);

}  // namespace orb::render::test
