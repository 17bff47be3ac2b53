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

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "orb/denoise/denoise_exr.h"
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

const std::vector<std::string> kGuided{"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z"};

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
