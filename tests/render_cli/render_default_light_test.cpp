// A glTF asset without any light renders under the default light
// (orb/import/gltf.h): a neutral grey environment, seen directly as the
// background at exactly its radiance, and a key light that shows the
// spheres at mid-grey, as the asset's reference screenshot does, rather than
// the old white backdrop they vanished into.
#include <algorithm>
#include <cmath>
#include <vector>

#include "cli_fixture.h"
#include "orb/import/gltf.h"

using namespace orb::test;
using orb::exr::testing::read_raw_exr;

namespace {

// Rec. 709 luma of pixel i.
float luminance(const orb::exr::testing::RawExr& image, std::size_t i) {
    return 0.2126f * image.channels.at("R")[i] + 0.7152f * image.channels.at("G")[i] +
           0.0722f * image.channels.at("B")[i];
}

}  // namespace

TEST_F(RenderCli, AnUnlitGltfAssetIsLitLikeItsReferenceScreenshot) {
    const std::string asset = std::string(ORB_TEST_DATA_DIR) +
                              "/gltf-sample-assets/MetalRoughSpheresNoTextures/MetalRoughSpheresNoTextures.glb";
    const auto run = render({asset, "--width", "128", "--height", "128", "--spp", "32", "--seed", "1", "-o",
                             path("spheres.exr")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.err.find("added a grey environment of radiance 0.05 and a key light"), std::string::npos) << run.err;
    const orb::exr::testing::RawExr image = read_raw_exr(path("spheres.exr"));
    std::vector<float> spheres;
    std::size_t background = 0;
    const std::vector<float>& alpha = image.channels.at("A");
    for (std::size_t i = 0; i < alpha.size(); ++i) {
        if (alpha[i] == 1.0f) spheres.push_back(luminance(image, i));
        if (alpha[i] != 0.0f) continue;
        // Every sample of a background pixel escapes to the environment: its radiance, up to
        // the float rounding of a mean of 32 equal samples. The key light is out of view.
        ++background;
        for (const char* c : {"R", "G", "B"})
            EXPECT_NEAR(image.channels.at(c)[i], orb::kDefaultEnvironmentRadiance, 1e-6) << "pixel " << i;
    }
    EXPECT_GT(background, alpha.size() / 10);
    // Mid-grey spheres: the median luminance of the reference screenshot's spheres is 0.183.
    // Over the wholly covered pixels it is 0.182-0.183 at 256x256 and 64 spp (seeds 1, 2), the
    // level the default was chosen for, and 0.192 here (the sphere edges weigh more at this
    // size); 0.02 either side still tells it from the old white backdrop or an unlit asset.
    ASSERT_GT(spheres.size(), alpha.size() / 3);
    std::nth_element(spheres.begin(), spheres.begin() + spheres.size() / 2, spheres.end());
    EXPECT_NEAR(spheres[spheres.size() / 2], 0.183, 0.02);
}
