// The albedo and normal layers that guide the denoiser (docs/orb-denoise.md,
// "What the guides hold"), against their definitions: behind a mirror the
// albedo is the mirror's tint times the colour of the diffuse surface it
// shows, and the normal is the mirror's own, at the first hit, facing the
// camera. Every sample of the pixels checked sees the same surfaces, so the
// means are exact up to each sample's float rounding and its rounding to
// the film's units (2^-25 at most) and, for the normal, the spread of
// directions within one pixel.
#include <gtest/gtest.h>

#include <cmath>

#include "render_test_support.h"

namespace orb::render::test {
namespace {

Vec3 pixel_mean(const Film& film, film::Channel channel, std::size_t pixel, std::uint64_t samples)
{
    const std::vector<double> sums = sum_values(film, channel);
    return {sums[pixel * 3] / static_cast<double>(samples), sums[pixel * 3 + 1] / static_cast<double>(samples),
            sums[pixel * 3 + 2] / static_cast<double>(samples)};
}

TEST(DenoiseGuides, AlbedoAndNormalBehindAMirror)
{
    const Vec3 wall{0.2, 0.5, 0.8};  // the enclosure: diffuse, and the only light
    const Vec3 tint{0.9, 0.6, 0.3};  // the mirror ball
    Scene scene;
    const int enclosure = add_sphere(scene, {0, 0, 0}, 50.0, add_material(scene, MaterialType::Diffuse, wall, {1, 1, 1}));
    const int mirror = add_sphere(scene, {0, 0, -10}, 2.0, add_material(scene, MaterialType::Mirror, tint));
    scene.camera.position = {0, 0, 0};
    scene.camera.target = {0, 0, -1};
    scene.camera.vfov_deg = 40.0;

    const int size = 32;
    const Film film = render(scene, small_config(size, size, 5), {16, 16});
    const std::uint64_t n = film.samples_per_pixel;
    const double rounding = static_cast<double>(n) * std::ldexp(1.0, -24);

    const std::vector<std::size_t> on_mirror = interior_pixels_of(film, mirror);
    const std::vector<std::size_t> on_wall = interior_pixels_of(film, enclosure);
    ASSERT_GT(on_mirror.size(), 50u);
    ASSERT_GT(on_wall.size(), 50u);
    for (std::size_t p : on_mirror) {
        const Vec3 albedo = pixel_mean(film, film::Channel::albedo, p, n);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(albedo[c], tint[c] * wall[c], tint[c] * wall[c] * rounding + 1e-6) << "mirror pixel " << p;
        // The mirror's normal faces the camera, which looks down -z from the
        // origin: every normal the pixel sees has z > 0.
        const Vec3 normal = pixel_mean(film, film::Channel::normal, p, n);
        EXPECT_GT(normal[2], 0.0) << "mirror pixel " << p;
    }
    for (std::size_t p : on_wall) {
        const Vec3 albedo = pixel_mean(film, film::Channel::albedo, p, n);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(albedo[c], wall[c], wall[c] * rounding + 1e-6) << "wall pixel " << p;
    }

    // The centre of the image sees the mirror head on: its normal there is
    // (0, 0, 1) within the directions the pixel's rays span (40 / 32 = 1.25
    // degrees a pixel; seen from the ball's centre, 2 units behind a surface
    // 8 units away, the normals turn by up to (8 + 2) / 2 = 5 times that).
    const std::size_t centre = static_cast<std::size_t>(size / 2) * size + size / 2;
    const Vec3 normal = pixel_mean(film, film::Channel::normal, centre, n);
    const double spread = std::sin(1.25 * 5.0 * M_PI / 180.0);
    EXPECT_NEAR(normal[0], 0.0, spread);
    EXPECT_NEAR(normal[1], 0.0, spread);
    EXPECT_NEAR(normal[2], 1.0, spread * spread);
}

}  // namespace
}  // namespace orb::render::test
