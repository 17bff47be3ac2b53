// libdenoise against what it promises: where it looks for OIDN, the choices
// it parses, that the RT filter with Orb's guides removes noise from an image
// whose answer is known (a uniform wall), and that the EXR step refuses
// values the filter would spread over their neighbourhood. Uses OIDN as
// scripts/install-deps.sh installs it.
#include <gtest/gtest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "orb/denoise/denoise_exr.h"
#include "orb/denoise/denoise_film.h"
#include "orb/denoise/denoiser.h"
#include "orb/denoise/oidn_library.h"
#include "orb/scene/error.h"

namespace orb::denoise {
namespace {

TEST(OidnLibrary, TheVariableAloneIsTriedWhenSet)
{
    const char* before = std::getenv(kLibraryVariable);
    const std::string saved = before ? before : "";
    unsetenv(kLibraryVariable);
    const std::vector<std::string> defaults = library_candidates();
    ASSERT_EQ(defaults.size(), 2u);
    EXPECT_EQ(defaults[0], installed_library_path());
    EXPECT_EQ(defaults[1], kLibraryName);

    setenv(kLibraryVariable, "/somewhere/libOpenImageDenoise.so.2", 1);
    EXPECT_EQ(library_candidates(), std::vector<std::string>{"/somewhere/libOpenImageDenoise.so.2"});
    // A folder names the library inside it.
    const std::string folder = std::filesystem::temp_directory_path().string();
    setenv(kLibraryVariable, folder.c_str(), 1);
    EXPECT_EQ(library_candidates(), std::vector<std::string>{(std::filesystem::path(folder) / kLibraryName).string()});
    if (before)
        setenv(kLibraryVariable, saved.c_str(), 1);
    else
        unsetenv(kLibraryVariable);
}

TEST(DenoiseChoices, ParseTheDocumentedNames)
{
    EXPECT_EQ(parse_device_choice("default"), DeviceChoice::Default);
    EXPECT_EQ(parse_device_choice("cpu"), DeviceChoice::Cpu);
    EXPECT_EQ(parse_device_choice("cuda"), DeviceChoice::Cuda);
    EXPECT_THROW(parse_device_choice("gpu"), std::invalid_argument);
    EXPECT_EQ(parse_quality("high"), Quality::High);
    EXPECT_EQ(parse_quality("balanced"), Quality::Balanced);
    EXPECT_EQ(parse_quality("fast"), Quality::Fast);
    EXPECT_THROW(parse_quality("best"), std::invalid_argument);
    EXPECT_STREQ(quality_name(Quality::Balanced), "balanced");
}

// A wall of albedo 0.5 lit to radiance 0.5, facing the camera, rendered with
// Gaussian noise of standard deviation 0.2 a pixel (what a few samples
// leave): the filter's output must be closer to 0.5 than the mean of 16
// times the samples would be, i.e. its mean squared error below a 16th of
// the noisy image's (0.04 / 16).
TEST(Denoiser, RemovesNoiseFromAUniformWall)
{
    const int width = 96, height = 64;
    const std::size_t floats = static_cast<std::size_t>(width) * height * 3;
    std::vector<float> color(floats), albedo(floats, 0.5f), normal(floats);
    std::mt19937 random(7);
    std::normal_distribution<float> noise(0.0f, 0.2f);
    for (std::size_t i = 0; i < floats; ++i) color[i] = std::max(0.0f, 0.5f + noise(random));
    for (std::size_t i = 0; i < floats; i += 3) normal[i + 2] = 1.0f;

    Denoiser denoiser(DenoiseSettings{DeviceChoice::Cpu, Quality::High});
    EXPECT_EQ(denoiser.device_name(), "CPU");
    EXPECT_EQ(denoiser.version().substr(0, 2), "2.");
    const std::vector<float> result = denoiser.denoise({width, height, color.data(), albedo.data(), normal.data()});
    ASSERT_EQ(result.size(), floats);
    double noisy = 0, denoised = 0;
    for (std::size_t i = 0; i < floats; ++i) {
        noisy += (color[i] - 0.5) * (color[i] - 0.5);
        denoised += (result[i] - 0.5) * (result[i] - 0.5);
    }
    noisy /= static_cast<double>(floats);
    denoised /= static_cast<double>(floats);
    EXPECT_LT(denoised, noisy / 16) << "noisy MSE " << noisy << ", denoised " << denoised;
    EXPECT_THROW(denoiser.denoise({width, height, color.data(), nullptr, normal.data()}), std::invalid_argument);
}

const std::vector<std::string> kGuided{"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z"};

// Guides as noisy as the beauty (what a few samples leave behind glass): a
// wall whose left half has albedo 0.25 and right half 0.75, lit so that its
// radiance equals its albedo, the colour with noise of standard deviation
// 0.2 and the albedo with 0.1 a pixel. Prefiltering the guides (OIDN's
// cleanAux) must remove the noise as the plain filter does (MSE below a 16th
// of the noisy image's), leave the caller's guides as they were, and differ
// from the plain filter's result (it runs other filters).
TEST(Denoiser, PrefilteredGuidesRemoveNoiseToo)
{
    const int width = 96, height = 64;
    const std::size_t floats = static_cast<std::size_t>(width) * height * 3;
    std::vector<float> truth(floats), color(floats), albedo(floats), normal(floats);
    std::mt19937 random(11);
    std::normal_distribution<float> colour_noise(0.0f, 0.2f), albedo_noise(0.0f, 0.1f);
    for (std::size_t i = 0; i < floats; ++i) {
        const bool right = (i / 3) % static_cast<std::size_t>(width) >= static_cast<std::size_t>(width / 2);
        truth[i] = right ? 0.75f : 0.25f;
        color[i] = std::max(0.0f, truth[i] + colour_noise(random));
        albedo[i] = std::clamp(truth[i] + albedo_noise(random), 0.0f, 1.0f);
    }
    for (std::size_t i = 0; i < floats; i += 3) normal[i + 2] = 1.0f;
    const std::vector<float> albedo_given = albedo, normal_given = normal;

    DenoiseSettings settings{DeviceChoice::Cpu, Quality::High};
    settings.prefilter_aux = true;
    Denoiser prefiltering(settings);
    EXPECT_NE(prefiltering.description().find("albedo and normal (prefiltered, clean)"), std::string::npos)
        << prefiltering.description();
    const std::vector<float> result = prefiltering.denoise({width, height, color.data(), albedo.data(), normal.data()});
    ASSERT_EQ(result.size(), floats);
    EXPECT_EQ(albedo, albedo_given);
    EXPECT_EQ(normal, normal_given);
    double noisy = 0, denoised = 0;
    for (std::size_t i = 0; i < floats; ++i) {
        noisy += (color[i] - truth[i]) * (color[i] - truth[i]);
        denoised += (result[i] - truth[i]) * (result[i] - truth[i]);
    }
    EXPECT_LT(denoised, noisy / 16) << "noisy MSE " << noisy / floats << ", denoised " << denoised / floats;

    Denoiser plain(DenoiseSettings{DeviceChoice::Cpu, Quality::High});
    EXPECT_NE(plain.description().find("albedo and normal (not clean)"), std::string::npos) << plain.description();
    EXPECT_NE(plain.denoise({width, height, color.data(), albedo.data(), normal.data()}), result);
}

// The denoised layer as the film encoder computes it (denoise_film.h) makes
// the same checks as the EXR step.
TEST(DenoisedPostLayer, RefusesMissingLayersAndValuesThatAreNotFinite)
{
    Denoiser denoiser(DenoiseSettings{DeviceChoice::Cpu, Quality::Fast});
    const exr::PostLayerPlanes layer = denoised_post_layer(denoiser, "the rendered image");
    ASSERT_EQ(layer.attributes.size(), 1u);
    EXPECT_EQ(layer.attributes[0].first, kDenoisedAttribute);
    EXPECT_EQ(layer.attributes[0].second, denoiser.description());
    const int width = 4, height = 2;
    std::vector<std::vector<float>> planes(kGuided.size(), std::vector<float>(width * height, 0.25f));
    const auto image = [&](std::size_t channels) {
        std::vector<exr::StoredImage::Channel> list;
        for (std::size_t c = 0; c < channels; ++c) list.push_back({kGuided[c], planes[c], false});
        return exr::StoredImage(width, height, list);
    };
    std::vector<std::vector<float>> denoised(3, std::vector<float>(width * height, -1.0f));
    const std::vector<std::span<float>> out{denoised[0], denoised[1], denoised[2]};
    layer.compute(image(kGuided.size()), out);
    for (const std::vector<float>& channel : denoised)
        for (const float value : channel) EXPECT_TRUE(std::isfinite(value) && value >= 0) << value;  // every value written
    try {
        layer.compute(image(7), out);  // no normal
        ADD_FAILURE() << "an image without normals was denoised";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("the rendered image: no normal layer (N.X, N.Y, N.Z)"), std::string::npos)
            << e.what();
    }
    planes[1][1] = std::numeric_limits<float>::quiet_NaN();  // G at pixel (1, 0)
    try {
        layer.compute(image(kGuided.size()), out);
        ADD_FAILURE() << "a beauty holding NaN was denoised";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("the rendered image: beauty pixel (1, 0) channel G is"), std::string::npos)
            << e.what();
    }
}

// An EXR of the given channels, every one `value` but R at pixel (1, 0).
std::string exr_bytes(const std::vector<std::string>& channels, float r_at_1_0)
{
    const int width = 4, height = 2;
    Imf::Header header(width, height);
    for (const std::string& name : channels) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    std::vector<std::vector<float>> planes(channels.size(), std::vector<float>(width * height, 0.25f));
    Imf::FrameBuffer buffer;
    for (std::size_t c = 0; c < channels.size(); ++c) {
        if (channels[c] == "R") planes[c][1] = r_at_1_0;
        buffer.insert(channels[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(planes[c].data()), sizeof(float),
                                              sizeof(float) * width));
    }
    const std::string path = (std::filesystem::temp_directory_path() / "orb-denoiser-test.exr").string();
    {
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(buffer);
        file.writePixels(height);
    }
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::filesystem::remove(path);
    return bytes;
}

TEST(DenoiseExr, RefusesValuesThatAreNotFinite)
{
    Denoiser denoiser(DenoiseSettings{DeviceChoice::Cpu, Quality::Fast});
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        try {
            add_denoised_layer(exr_bytes(kGuided, bad), "bad.exr", denoiser);
            ADD_FAILURE() << "a beauty holding " << bad << " was denoised";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("bad.exr: beauty pixel (1, 0) channel R is"), std::string::npos)
                << e.what();
        }
    }
    EXPECT_NO_THROW(add_denoised_layer(exr_bytes(kGuided, 0.5f), "good.exr", denoiser));
}

TEST(DenoiseExr, NamesTheMissingLayers)
{
    Denoiser denoiser(DenoiseSettings{DeviceChoice::Cpu, Quality::Fast});
    const std::vector<std::string> no_normal{"R", "G", "B", "albedo.R", "albedo.G", "albedo.B"};
    try {
        add_denoised_layer(exr_bytes(no_normal, 0.5f), "x.exr", denoiser);
        ADD_FAILURE() << "an image without normals was denoised";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("x.exr: no normal layer (N.X, N.Y, N.Z)"), std::string::npos) << e.what();
    }
    try {
        add_denoised_layer(exr_bytes({"albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z"}, 0.5f), "y.exr", denoiser);
        ADD_FAILURE() << "an image without a beauty was denoised";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("y.exr: no beauty layer (R, G, B)"), std::string::npos) << e.what();
    }
    EXPECT_THROW(add_denoised_layer("v/1\x01 but short", "z.exr", denoiser), InputError);
}

}  // namespace
}  // namespace orb::denoise
