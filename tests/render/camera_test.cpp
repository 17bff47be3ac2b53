// Camera framing: where spheres land in the image, and how big they are.
#include <gtest/gtest.h>

#include <cmath>

#include "render_test_support.h"

namespace orb::render::test {
namespace {

Scene single_sphere_scene(Vec3 centre, double radius)
{
    Scene scene;
    add_sphere(scene, centre, radius, add_material(scene, MaterialType::Diffuse, {0.5, 0.5, 0.5}, {1, 1, 1}));
    scene.camera.position = {0, 0, 10};
    scene.camera.target = {0, 0, 0};
    scene.camera.up = {0, 1, 0};
    scene.camera.vfov_deg = 30;
    return scene;
}

int id_at(const Film& film, int x, int y) { return static_cast<int>(film.object_id[y * film.width + x]); }

TEST(Camera, SphereOnTheAxisIsCentredAndSizedByTheFieldOfView)
{
    const int w = 65, h = 49;  // odd: one pixel centre lies on the axis
    const double radius = 1.5;
    const Film film = render(single_sphere_scene({0, 0, 0}, radius), small_config(w, h), {1});
    double cx = 0, cy = 0, count = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (id_at(film, x, y) == 0) cx += x + 0.5, cy += y + 0.5, ++count;
    ASSERT_GT(count, 0);
    EXPECT_NEAR(cx / count, w / 2.0, 1e-9);
    EXPECT_NEAR(cy / count, h / 2.0, 1e-9);
    // Its silhouette is a disc of angular radius asin(r / D); on the image
    // plane that is tan(asin(r / D)) / tan(vfov / 2) * h / 2 pixels.
    const double angular = std::asin(radius / 10.0);
    const double pixels_radius = std::tan(angular) / std::tan(15.0 * M_PI / 180.0) * h / 2.0;
    const double expected_area = M_PI * pixels_radius * pixels_radius;
    EXPECT_NEAR(count, expected_area, 2.0 * M_PI * pixels_radius);  // one pixel of slack around the rim
    EXPECT_NEAR(film.depth[(h / 2) * w + w / 2], 10.0 - radius, 1e-3);
    EXPECT_TRUE(std::isinf(film.depth[0]));
    EXPECT_EQ(film.alpha[0], 0.0f);
}

TEST(Camera, RightIsPositiveXAndTheTopRowComesFirst)
{
    const int w = 32, h = 32;
    // Half-way to the edge of the view at distance 10: 0.5 * 10 * tan(15 deg) = 1.34.
    const Film right = render(single_sphere_scene({1.34, 0, 0}, 0.5), small_config(w, h), {1});
    EXPECT_EQ(id_at(right, 3 * w / 4, h / 2), 0);
    EXPECT_EQ(id_at(right, w / 4, h / 2), -1);
    const Film up = render(single_sphere_scene({0, 1.34, 0}, 0.5), small_config(w, h), {1});
    EXPECT_EQ(id_at(up, w / 2, h / 4), 0);
    EXPECT_EQ(id_at(up, w / 2, 3 * h / 4), -1);
}

TEST(Camera, ThinLensKeepsTheFocalPlaneSharpAndBlursTheRest)
{
    Scene scene = single_sphere_scene({0, 0, 0}, 1.0);
    scene.camera.aperture = 1.0;
    scene.camera.focus_distance = 9.0;  // the sphere's front
    const Film film = render(scene, small_config(32, 32), {64});
    // The centre is covered by every sample; the film stays finite and symmetric.
    EXPECT_EQ(film.alpha[16 * 32 + 16], 64.0f);
    for (float a : film.alpha) EXPECT_LE(a, 64.0f);
    // With a lens, coverage near the silhouette is fractional (a pinhole pixel
    // seen through 64 jittered samples is mostly 0 or 64 far from the rim).
    int fractional = 0;
    for (float a : film.alpha) fractional += a > 0.0f && a < 64.0f;
    Scene pinhole = scene;
    pinhole.camera.aperture = 0.0;
    const Film sharp = render(pinhole, small_config(32, 32), {64});
    int sharp_fractional = 0;
    for (float a : sharp.alpha) sharp_fractional += a > 0.0f && a < 64.0f;
    EXPECT_GT(fractional, sharp_fractional);
}

}  // namespace
}  // namespace orb::render::test
