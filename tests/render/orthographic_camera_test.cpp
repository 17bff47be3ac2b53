// The orthographic camera against closed forms: parallel rays see a sphere
// of radius r as a disc of area pi r^2 at every distance, so the image's mean
// coverage (the alpha channel) is pi r^2 / (view height x view width) however
// far the camera is, where a perspective camera's falls with the distance;
// the depth of each pixel centre is that of a parallel ray; and a thin lens
// in front of an orthographic camera (telecentric: every pixel's cone of
// rays has the same aperture) shows the sphere's oblique parallel projections.
//
// Tolerances: a sample's alpha is 0 or 1. A pixel whose square lies wholly
// inside or outside every silhouette a sample can see has a fixed alpha; the
// others ("uncertain" pixels) add at most 1/4 per sample to the variance of
// the summed alpha. So the mean coverage over W x H pixels and n samples
// each has a standard deviation of at most sqrt(uncertain n / 4) / (n W H),
// and the checks allow 4 of those.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render_test_support.h"

namespace orb::render::test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kWidth = 64, kHeight = 48, kSpp = 64;

// An emitting sphere of radius `radius` at the origin, seen along -z from distance `distance`.
Scene sphere_seen_from(double distance, double radius, double orthographic_height)
{
    Scene scene;
    add_sphere(scene, {0, 0, 0}, radius, add_material(scene, MaterialType::Diffuse, {0.5, 0.5, 0.5}, {1, 1, 1}));
    scene.camera.position = {0, 0, distance};
    scene.camera.target = {0, 0, 0};
    scene.camera.up = {0, 1, 0};
    scene.camera.vfov_deg = 30;
    scene.camera.orthographic_height = orthographic_height;
    return scene;
}

// The mean of the alpha channel over every pixel and sample: the fraction of the view the sphere covers.
double mean_coverage(const Film& film)
{
    double sum = 0;
    for (float a : film.alpha) sum += a;
    return sum / (double(film.samples_per_pixel) * film.width * film.height);
}

// Pixels (of a kWidth x kHeight image, centre of view at its centre) that
// the silhouettes, discs between radius `inner` and `outer` pixels about the
// centre, may cross: those whose square reaches inside `outer` and outside `inner`.
int uncertain_pixels(double inner, double outer)
{
    int count = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const double x0 = x - kWidth / 2.0, x1 = x0 + 1, y0 = y - kHeight / 2.0, y1 = y0 + 1;
            const double near_x = std::clamp(0.0, x0, x1), near_y = std::clamp(0.0, y0, y1);
            const double far_x = std::max(std::fabs(x0), std::fabs(x1)), far_y = std::max(std::fabs(y0), std::fabs(y1));
            count += std::hypot(near_x, near_y) < outer && std::hypot(far_x, far_y) > inner;
        }
    return count;
}

// Four standard deviations of mean_coverage's bound (see the top of the file).
double coverage_tolerance(int uncertain) { return 4.0 * std::sqrt(uncertain * kSpp / 4.0) / (double(kSpp) * kWidth * kHeight); }

// One path per work-item (as on GPUs) and the CPU's lanes each.
const char* const kKernels[] = {"0", "16"};

TEST(OrthographicCamera, CoverageOfASphereIsItsAreaOverTheViewsAtEveryDistance)
{
    const double radius = 1, view_height = 4, view_width = view_height * kWidth / kHeight;
    const double expected = kPi * radius * radius / (view_height * view_width);
    const double pixels_per_unit = kHeight / view_height;
    const double tolerance = coverage_tolerance(uncertain_pixels(radius * pixels_per_unit, radius * pixels_per_unit));
    ASSERT_LT(tolerance, 0.01 * expected) << "the test must resolve a 1% change";
    for (const char* lanes : kKernels)
        for (const double distance : {1.5, 10.0, 1000.0}) {
            const Film film = render_with_simd_lanes(sphere_seen_from(distance, radius, view_height),
                                                     small_config(kWidth, kHeight), {kSpp}, lanes);
            EXPECT_NEAR(mean_coverage(film), expected, tolerance) << "distance " << distance << ", lanes " << lanes;
        }
}

// The same sphere through a perspective camera of vfov 30 degrees: its
// silhouette is a cone of half-angle asin(r / D), a disc of radius
// tan(asin(r / D)) on the image plane at unit distance, which is
// 2 tan(15 deg) high. The coverage depends on D, unlike the orthographic one's.
TEST(OrthographicCamera, APerspectiveCamerasCoverageFallsWithTheDistance)
{
    const double radius = 1, half_height = std::tan(15.0 * kPi / 180), half_width = half_height * kWidth / kHeight;
    double previous = INFINITY;
    for (const double distance : {5.0, 10.0, 20.0}) {
        const double disc = std::tan(std::asin(radius / distance));
        const double expected = kPi * disc * disc / (4 * half_height * half_width);
        const double disc_pixels = disc / half_height * kHeight / 2;
        const Film film = render(sphere_seen_from(distance, radius, 0.0), small_config(kWidth, kHeight), {kSpp});
        const double coverage = mean_coverage(film);
        EXPECT_NEAR(coverage, expected, coverage_tolerance(uncertain_pixels(disc_pixels, disc_pixels)))
            << "distance " << distance;
        EXPECT_LT(coverage, previous / 3) << "distance " << distance;
        previous = coverage;
    }
}

// The centre ray of pixel (x, y) starts on the camera's plane at the pixel
// centre's place in the view and runs parallel to the view: it meets the
// sphere at depth D - sqrt(r^2 - rho^2), rho its distance from the axis.
TEST(OrthographicCamera, EveryPixelsDepthIsThatOfAParallelRay)
{
    const double radius = 1.5, distance = 10, view_height = 4;
    const double unit = view_height / kHeight;  // scene units per pixel
    for (const char* lanes : kKernels) {
        const Film film = render_with_simd_lanes(sphere_seen_from(distance, radius, view_height),
                                                 small_config(kWidth, kHeight), {1}, lanes);
        int hits = 0, inside = 0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const double sx = (x + 0.5 - kWidth / 2.0) * unit, sy = (kHeight / 2.0 - y - 0.5) * unit;
                const double rho2 = sx * sx + sy * sy;
                const float depth = film.depth[y * kWidth + x];
                // Rays that pass within float rounding of the rim may go either way.
                if (std::fabs(std::sqrt(rho2) - radius) < 1e-4) continue;
                inside += rho2 < radius * radius;
                if (rho2 > radius * radius) {
                    EXPECT_TRUE(std::isinf(depth)) << x << "," << y;
                } else {
                    ++hits;
                    EXPECT_NEAR(depth, distance - std::sqrt(radius * radius - rho2), 1e-4) << x << "," << y;
                }
            }
        // Every pixel centre inside the disc (about pi 18^2 of them) was checked.
        EXPECT_EQ(hits, inside) << lanes;
        EXPECT_GT(hits, 1000) << lanes;
    }
}

// A thin lens of radius R focused at the sphere's centre (focus_distance = D):
// for a lens point l, every ray runs along D forward - l from the film point
// + l, an oblique parallel projection centred where the pinhole's is. The
// sphere's shadow along a direction at angle theta to the view is an ellipse
// of area pi r^2 / cos(theta), cos(theta) = D / sqrt(D^2 + |l|^2). Averaged
// over the lens disc: pi r^2 (2 / (3 R^2 D)) ((D^2 + R^2)^(3/2) - D^3).
TEST(OrthographicCamera, AThinLensShowsTheAverageOfTheSpheresObliqueProjections)
{
    const double radius = 1, distance = 2, lens_radius = 0.5, view_height = 4;
    const double view_width = view_height * kWidth / kHeight;
    const double mean_stretch =
        2.0 / (3.0 * lens_radius * lens_radius * distance) *
        (std::pow(distance * distance + lens_radius * lens_radius, 1.5) - distance * distance * distance);
    const double expected = kPi * radius * radius * mean_stretch / (view_height * view_width);
    const double pinhole = kPi * radius * radius / (view_height * view_width);
    const double pixels_per_unit = kHeight / view_height;
    // The ellipses lie between the disc of radius r and that of radius r / cos(theta_max).
    const double outer = radius * std::hypot(distance, lens_radius) / distance;
    const double tolerance = coverage_tolerance(uncertain_pixels(radius * pixels_per_unit, outer * pixels_per_unit));
    ASSERT_LT(tolerance, (expected - pinhole) / 2) << "the test must tell the lens from a pinhole";
    Scene scene = sphere_seen_from(distance, radius, view_height);
    scene.camera.aperture = 2 * lens_radius;
    scene.camera.focus_distance = distance;
    for (const char* lanes : kKernels) {
        const Film film = render_with_simd_lanes(scene, small_config(kWidth, kHeight), {kSpp}, lanes);
        EXPECT_NEAR(mean_coverage(film), expected, tolerance) << lanes;
    }
}

}  // namespace
}  // namespace orb::render::test
