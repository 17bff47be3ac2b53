// An orthographic camera from a real asset, through the tools: the Khronos
// sample "Cameras" (tests/data/gltf-sample-assets/Cameras, CC0) holds one
// quad and, at the same node position, a perspective camera and an
// orthographic one (xmag = ymag = 1). orb-import takes either with --camera;
// the quad comes in as its bounding sphere (--non-spheres bound). Rendered,
// the orthographic view's coverage (alpha) is that sphere's disc over the
// 2 x 2 view, and its EXR's worldToNDC is the affine orthographic matrix.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>

#include "cli_fixture.h"
#include "orb/exr/camera_matrices.h"
#include "orb/scene/scene_json.h"

using namespace orb::test;

namespace {

const std::string kAsset = std::string(ORB_TEST_DATA_DIR) + "/gltf-sample-assets/Cameras/Cameras.gltf";

std::string quoted(const std::string& text) { return "'" + text + "'"; }

class RenderOrthographic : public RenderCli {
protected:
    // orb-import's scene for the asset's camera `camera`, written to `name`.
    orb::Scene import_camera(const std::string& camera, const std::string& name) {
        const std::string command = quoted(ORB_IMPORT_EXE) + " " + quoted(kAsset) + " --camera " + camera +
                                    " --non-spheres bound -o " + quoted(path(name));
        const auto run = run_process({"/bin/sh", "-c", command});
        EXPECT_EQ(run.exit_code, 0) << command << "\n" << run.err;
        return orb::load_scene_json(read_text(path(name)), name);
    }
    static std::string read_text(const std::string& file) {
        std::ifstream in(file);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
};

double mean_alpha(const orb::Film& film) {
    double sum = 0;
    for (float a : film.alpha) sum += a;
    return sum / (double(film.samples_per_pixel) * film.width * film.height);
}

}  // namespace

TEST_F(RenderOrthographic, TheKhronosCamerasAssetsOrthographicCameraRendersItsView) {
    if (std::string(ORB_IMPORT_EXE).empty()) GTEST_SKIP() << "this build has no orb-import";
    const orb::Scene scene = import_camera("1", "ortho.json");
    EXPECT_EQ(scene.camera.orthographic_height, 2.0);  // 2 ymag
    EXPECT_EQ(scene.render.width, 480);                // xmag/ymag = 1
    EXPECT_EQ(scene.render.height, 480);
    ASSERT_EQ(scene.spheres.size(), 2u);  // the quad's bounding sphere, and the default key light (out of view)
    const double radius = scene.spheres[0].radius;
    EXPECT_NEAR(radius, std::sqrt(0.5), 1e-4);  // the unit quad's half diagonal

    const int size = 48, spp = 16;
    const auto run = render({path("ortho.json"), "--width", std::to_string(size), "--height", std::to_string(size),
                             "--spp", std::to_string(spp), "-o", path("ortho.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto file = orb::exr::read_film_exr(path("ortho.exr"));
    EXPECT_TRUE(orb::exr::is_orthographic(file.metadata.world_to_ndc));
    // The disc's area over the view's, 2 x 2. A sample's alpha is 0 or 1;
    // only the pixels the rim crosses (at most 8 ceil(r) + 4 for a circle of
    // r pixels) vary, each by at most 1/4 per sample: four standard deviations.
    const double expected = std::numbers::pi * radius * radius / 4.0;
    const double rim_pixels = 8 * std::ceil(radius * size / 2.0) + 4;
    const double tolerance = 4 * std::sqrt(rim_pixels * spp / 4.0) / (double(spp) * size * size);
    EXPECT_NEAR(mean_alpha(file.film), expected, tolerance);

    // The asset's perspective camera, at the same place (40 degrees high, 3.4 units from the sphere), sees it
    // smaller: about pi tan^2(asin(r / 3.36)) / (4 tan^2(20 degrees)) = 0.28 of its view.
    const orb::Scene perspective = import_camera("0", "perspective.json");
    EXPECT_EQ(perspective.camera.orthographic_height, 0.0);
    ASSERT_EQ(render({path("perspective.json"), "--width", std::to_string(size), "--height", std::to_string(size),
                      "--spp", std::to_string(spp), "-o", path("perspective.exr")})
                  .exit_code,
              0);
    const auto seen = orb::exr::read_film_exr(path("perspective.exr"));
    EXPECT_FALSE(orb::exr::is_orthographic(seen.metadata.world_to_ndc));
    EXPECT_LT(mean_alpha(seen.film), expected - 10 * tolerance);
}
