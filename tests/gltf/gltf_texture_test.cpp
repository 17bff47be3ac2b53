// Textures read into sphere materials (docs/gltf.md, "Textures"), through
// the OpenImageIO decoder the tools use: the generated assets of
// make_gltf.py textures() and bad_images(), whose answers follow from the
// texels written there, and the decoder on damaged PNG and JPEG bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "gltf_test_util.h"
#include "orb/image/texture_decoder.h"
#include "orb/scene/error.h"

namespace orb::gltf_test {
namespace {

// Texels are stored as float: a value read back is within this of k / 255.
constexpr double kTexelRounding = 1e-6;

double srgb_to_linear(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

GltfImportOptions with_decoder() {
    GltfImportOptions options;
    options.image_decoder = image::texture_decoder();
    return options;
}

const Material& material_of(const Scene& scene, const std::string& sphere) {
    return scene.materials[sphere_named(scene, sphere).material];
}

void expect_color(const Vec3& actual, const Vec3& expected) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], kTexelRounding) << "channel " << c;
}

// The same asset with its images in bufferViews (.gltf + .bin, data-URI
// buffer, .glb), as data: URIs and as PNG files beside the .gltf.
class Textures : public ::testing::TestWithParam<std::string> {};

TEST_P(Textures, AtlasCellsBecomeOneMaterialPerDistinctValue) {
    const GltfImportResult result = import_generated("textures" + GetParam(), with_decoder());
    const Scene& scene = result.scene;
    const double red = srgb_to_linear(188.0 / 255.0);

    // A0: metallic-roughness cell [0][1], base-colour cell [0][1].
    const Material& a0 = material_of(scene, "A.0");
    EXPECT_EQ(a0.type, MaterialType::Pbr);
    EXPECT_NEAR(a0.roughness, 102.0 / 255.0, kTexelRounding);
    EXPECT_NEAR(a0.metallic, 0.0, kTexelRounding);
    expect_color(a0.color, {red, 0.0, 0.0});
    // A1 samples the same cells: the same material, not a copy.
    EXPECT_EQ(sphere_named(scene, "A.1").material, sphere_named(scene, "A.0").material);
    // A2: KHR_texture_transform's offset wraps (REPEAT) into cell [0][0]; base colour clamps.
    const Material& a2 = material_of(scene, "A.2");
    EXPECT_NEAR(a2.roughness, 51.0 / 255.0, kTexelRounding);
    EXPECT_NEAR(a2.metallic, 0.5 * 255.0 / 255.0, kTexelRounding);  // metallicFactor 0.5
    expect_color(a2.color, {red, 0.0, 0.0});
    // A3: cell [1][0]; TEXCOORD_1 clamps to base-colour cell [1][1], times baseColorFactor's 0.5 green.
    const Material& a3 = material_of(scene, "A.3");
    EXPECT_NEAR(a3.roughness, 153.0 / 255.0, kTexelRounding);
    EXPECT_NEAR(a3.metallic, 0.5 * 128.0 / 255.0, kTexelRounding);
    expect_color(a3.color, {0.0, 0.5 * red, 0.0});

    std::set<std::string> atlas_names;
    for (const Sphere& s : scene.spheres)
        if (s.name.rfind("A.", 0) == 0) atlas_names.insert(scene.materials[s.material].name);
    EXPECT_EQ(atlas_names, (std::set<std::string>{"Atlas #1", "Atlas #2", "Atlas #3"}));

    // Gradient: half its area reads 0, half 255 -> the averages.
    const Material& gradient = material_of(scene, "Gradient");
    EXPECT_NEAR(gradient.roughness, 0.5, kTexelRounding);
    EXPECT_NEAR(gradient.metallic, 0.5, kTexelRounding);
    expect_color(gradient.color, {1.0, 1.0, 1.0});

    // Glow: emissiveFactor x the sRGB-decoded emissive texel.
    const Material& glow = material_of(scene, "Glow");
    expect_color(glow.emission, {srgb_to_linear(188.0 / 255.0), 0.5 * srgb_to_linear(94.0 / 255.0), 0.25});

    // Two warnings: the averaged sphere, and the normal texture that is not read.
    ASSERT_EQ(result.warnings.size(), 2u) << ::testing::PrintToString(result.warnings);
    EXPECT_TRUE(any_warning_contains(result, "textures vary over 1 sphere (Gradient; Gradient #1): each takes its "
                                             "textures' area-weighted average"))
        << ::testing::PrintToString(result.warnings);
    EXPECT_TRUE(any_warning_contains(result, ": ignored: 1 normal texture")) << ::testing::PrintToString(result.warnings);
}

TEST_P(Textures, StrictRefusesAnAveragedTexture) {
    GltfImportOptions options = with_decoder();
    options.strict = true;
    try {
        import_generated("textures" + GetParam(), options);
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("textures vary over 1 sphere"), std::string::npos) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Gltf, Textures,
                         ::testing::Values(".gltf", "_embedded.gltf", ".glb", "_data_uri.gltf", "_files.gltf"));

TEST(Textures, WithoutADecoderOnlyTheFactorsCountAndTheWarningSaysWhy) {
    const GltfImportResult result = import_generated("textures.glb");
    const Material& atlas = material_of(result.scene, "A.0");
    EXPECT_EQ(atlas.name, "Atlas");
    expect_color(atlas.color, {1.0, 0.5, 1.0});
    EXPECT_DOUBLE_EQ(atlas.roughness, 1.0);
    EXPECT_DOUBLE_EQ(atlas.metallic, 0.5);
    EXPECT_EQ(sphere_named(result.scene, "A.3").material, sphere_named(result.scene, "A.0").material);
    ASSERT_EQ(result.warnings.size(), 1u) << ::testing::PrintToString(result.warnings);
    EXPECT_EQ(result.warnings[0], generated("textures.glb") +
                                      ": ignored: 1 base-colour texture, 2 metallic-roughness textures, 1 normal "
                                      "texture, 1 emissive texture (textures are read only when the importer is given an image decoder)");
}

// Four broken images: each is named in a warning and its material keeps its factor.
TEST(Textures, BrokenImagesAreWarnedAboutNeverFatal) {
    const GltfImportResult result = import_generated("bad_images.gltf", without_default_light(with_decoder()));
    ASSERT_EQ(result.scene.spheres.size(), 4u);
    for (int k = 0; k < 4; ++k)
        expect_color(material_of(result.scene, "Ball" + std::to_string(k)).color, {0.1 * (k + 1), 0.5, 0.5});
    const std::string all = ::testing::PrintToString(result.warnings);
    EXPECT_TRUE(any_warning_contains(result, "image 0 'garbage'")) << all;
    EXPECT_TRUE(any_warning_contains(result, "image 1 'truncated'")) << all;
    EXPECT_TRUE(any_warning_contains(result, "image 2 'huge'")) << all;
    EXPECT_TRUE(any_warning_contains(result, "image too large (100000x100000")) << all;
    EXPECT_TRUE(any_warning_contains(result, "image 3 'missing' (material 'missing' base-colour texture): "
                                             "'missing.png' could not be read")) << all;
    EXPECT_EQ(result.warnings.size(), 4u) << all;

    GltfImportOptions strict = with_decoder();
    strict.strict = true;
    EXPECT_THROW(import_generated("bad_images.gltf", strict), InputError);
}

// A 64 x 48 JPEG of a colour gradient, written by OpenImageIO's libjpeg.
std::string gradient_jpeg() {
    const int width = 64, height = 48;
    std::vector<unsigned char> pixels(std::size_t(width) * height * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            unsigned char* p = &pixels[(std::size_t(y) * width + x) * 3];
            p[0] = static_cast<unsigned char>(x * 4);
            p[1] = static_cast<unsigned char>(y * 5);
            p[2] = static_cast<unsigned char>((x + y) * 2);
        }
    const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                       ("orb-texture-test-" + std::to_string(::getpid()) + ".jpg");
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out || !out->open(path.string(), OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8)) ||
        !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !out->close())
        throw std::runtime_error("cannot write " + path.string());
    const std::string bytes = read_file(path.string());
    std::filesystem::remove(path);
    return bytes;
}

// The decoder itself on every prefix and on bit flips of a real PNG and
// JPEG: an error or consistent texels, never a crash (ASan builds check reads).
TEST(TextureDecoder, CorruptBytesGiveAnErrorOrTexels) {
    for (const std::string& bytes : {read_file(generated("textures_files_image0.png")), gradient_jpeg()}) {
        std::size_t errors = 0, images = 0;
        auto attempt = [&](const std::string& candidate) {
            try {
                const DecodedImage decoded = image::decode_texture(candidate, "", "candidate");
                EXPECT_EQ(decoded.texels.size(),
                          std::size_t(decoded.width) * std::size_t(decoded.height) * std::size_t(decoded.channels));
                ++images;
            } catch (const InputError& e) {
                EXPECT_NE(std::string(e.what()).find("candidate"), std::string::npos) << e.what();
                ++errors;
            }
        };
        const std::size_t step = std::max<std::size_t>(1, bytes.size() / 200);
        for (std::size_t length = 0; length < bytes.size(); length += step) attempt(bytes.substr(0, length));
        for (std::size_t at = 0; at < bytes.size(); at += step) {
            std::string flipped = bytes;
            flipped[at] = char(flipped[at] ^ 0x5a);
            attempt(flipped);
        }
        EXPECT_GT(errors, 0u);
        attempt(bytes);
        EXPECT_GT(images, 0u);
    }
}


}  // namespace
// A real textured asset: the Khronos sample BoxTextured (a cube whose six
// faces each carry the whole Cesium logo, REPEAT over u in [0, 6]), its cube
// kept as a bounding sphere. The texture varies over that sphere, so its
// material is the texture's mean, sRGB-decoded, with one warning. Each face
// covers the texture once, so the area-weighted mean is the mean of the
// texels; the importer samples nearest texels at 2 x 32 x 32 points a face
// (0.00017 from the exact mean here), hence the 1e-3.
TEST(Textures, ARealTexturedBoxTakesItsTexturesMean) {
    const std::string path = std::string(ORB_GLTF_SAMPLE_ASSETS_DIR) + "/BoxTextured/BoxTextured.glb";
    GltfImportOptions options = without_default_light(with_decoder());
    options.non_spheres = NonSpherePolicy::Bound;
    const GltfImportResult result = import_gltf(read_file(path), path, "", options);
    ASSERT_EQ(result.scene.spheres.size(), 1u);
    const Material& m = result.scene.materials.at(result.scene.spheres[0].material);
    EXPECT_TRUE(any_warning_contains(result, "textures vary over 1 sphere (Mesh; Texture #1)"))
        << ::testing::PrintToString(result.warnings);

    // The embedded PNG's texels, decoded on their own and averaged.
    const std::string glb = read_file(path);
    const std::uint32_t json_length = *reinterpret_cast<const std::uint32_t*>(glb.data() + 12);
    const nlohmann::json json = nlohmann::json::parse(glb.substr(20, json_length));
    const nlohmann::json& view = json["bufferViews"][json["images"][0]["bufferView"].get<int>()];
    const std::size_t binary = 20 + json_length + 8;
    const DecodedImage logo = image::decode_texture(
        std::string_view(glb).substr(binary + view.value("byteOffset", 0), view["byteLength"].get<std::size_t>()),
        "image/png", "logo");
    ASSERT_GE(logo.channels, 3);
    double mean[3] = {0, 0, 0};
    const std::size_t texels = std::size_t(logo.width) * std::size_t(logo.height);
    for (std::size_t t = 0; t < texels; ++t)
        for (int c = 0; c < 3; ++c) mean[c] += srgb_to_linear(logo.texels[t * logo.channels + c]) / double(texels);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.color[c], mean[c], 1e-3) << "channel " << c;
}

}  // namespace orb::gltf_test
