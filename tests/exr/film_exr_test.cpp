#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfDoubleAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "orb/exr/film_exr.h"
#include "orb/scene/error.h"
#include "exr_channels.h"
#include "test_film.h"

using namespace orb::exr;
using orb::exr::testing::message_of;
using orb::exr::testing::scratch_path;
using orb::exr::testing::synthetic_film;
using orb::exr::testing::synthetic_metadata;
using orb::exr::testing::within_float_rounding;

namespace {

constexpr int kWidth = 8, kHeight = 6;

std::map<std::string, std::vector<float>> read_channels(const std::string& path) {
    return orb::exr::testing::read_raw_exr(path).channels;
}

// Sums rebuilt from stored means: within a few float roundings, plus the
// rounding to whole units.
void expect_sums_near(const std::vector<orb::film::Sum>& expected, const std::vector<orb::film::Sum>& actual,
                      const char* what, double ulps = 4) {
    ASSERT_EQ(expected.size(), actual.size()) << what;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const double a = static_cast<double>(expected[i]), b = static_cast<double>(actual[i]);
        ASSERT_TRUE(std::fabs(a - b) <= 1.0 || within_float_rounding(a, b, ulps))
            << what << "[" << i << "]: " << expected[i] << " vs " << actual[i];
    }
}

double value_of(orb::film::Sum sum) { return orb::film::sum_value(orb::film::Units::Fixed, sum); }

}  // namespace

TEST(FilmExr, RoundTripRecoversEverySumWithinFloatRounding) {
    const auto film = synthetic_film(kWidth, kHeight, 37);
    const std::string path = scratch_path("film.exr");
    write_film_exr(path, film, synthetic_metadata(), {});
    const ExrFilm back = read_film_exr(path);

    EXPECT_EQ(back.film.width, kWidth);
    EXPECT_EQ(back.film.height, kHeight);
    EXPECT_EQ(back.film.samples_per_pixel, 37u);
    EXPECT_EQ(back.passes, image_passes());  // the default: every layer but the sample counts
    EXPECT_FALSE(back.half);
    EXPECT_FALSE(back.exact);  // means only: the sums are rebuilt from them
    expect_sums_near(film.radiance, back.film.radiance, "radiance");
    expect_sums_near(film.direct, back.film.direct, "direct");
    expect_sums_near(film.indirect, back.film.indirect, "indirect");
    expect_sums_near(film.emission, back.film.emission, "emission");
    expect_sums_near(film.albedo, back.film.albedo, "albedo");
    expect_sums_near(film.alpha, back.film.alpha, "alpha");
    expect_sums_near(film.normal, back.film.normal, "normal");
    EXPECT_EQ(film.depth, back.film.depth);
    EXPECT_EQ(film.object_id, back.film.object_id);
    // sum_sq comes back through the variance of the mean and the mean: a
    // subtraction that can cost a few more roundings than the plain sums.
    expect_sums_near(film.radiance_sq, back.film.radiance_sq, "radiance_sq", 16);
}

// A file that may be continued or merged carries the film's exact sums:
// they come back bit for bit, and its visible channels are the very values
// of a file without them.
TEST(FilmExr, ExactSumsComeBackBitForBit) {
    auto film = synthetic_film(kWidth, kHeight, 37);
    film.radiance[5] = orb::film::kSumRangeEnd;  // beyond a float's and a double's integers
    film.normal[7] = -12345;                     // a signed sum
    for (const char* passes : {"all", "beauty,normal,variance,samples", "variance"}) {
        ExrWriteOptions options;
        options.passes = parse_passes(passes);
        options.exact_sums = true;
        const std::string path = scratch_path("exact.exr");
        write_film_exr(path, film, synthetic_metadata(), options);
        const ExrFilm back = read_film_exr(path);
        EXPECT_TRUE(back.exact) << passes;
        for (const orb::film::ChannelInfo& info : orb::film::kChannels) {
            const bool stored = orb::exr::contains(options.passes, info.layer);
            if (!stored || info.accumulation != orb::film::Accumulation::Sum) continue;
            EXPECT_EQ(back.film.sums(info.channel), film.sums(info.channel)) << passes << " " << info.name;
        }
        options.exact_sums = false;
        const std::string plain = scratch_path("plain.exr");
        write_film_exr(plain, film, synthetic_metadata(), options);
        const auto with = read_channels(path), without = read_channels(plain);
        for (const auto& [name, values] : without) {
            ASSERT_TRUE(with.count(name)) << name;
            EXPECT_EQ(with.at(name), values) << passes << " " << name;
        }
        for (const auto& [name, values] : with) {
            if (!without.count(name)) {
                EXPECT_EQ(name.rfind("orb.sum.", 0), 0u) << name;
            }
        }
    }
}

TEST(FilmExr, ExactSumsAreTwoUintChannelsPerComponent) {
    const std::string path = scratch_path("exact.exr");
    ExrWriteOptions options;
    options.passes = {Pass::Beauty, Pass::Depth};
    options.exact_sums = true;
    write_film_exr(path, synthetic_film(kWidth, kHeight, 3), synthetic_metadata(), options);
    Imf::InputFile file(path.c_str());
    std::set<std::string> names;
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
        names.insert(it.name());
        EXPECT_EQ(it.channel().type, std::string(it.name()).rfind("orb.sum.", 0) == 0 ? Imf::UINT : Imf::FLOAT)
            << it.name();
    }
    EXPECT_EQ(names, (std::set<std::string>{"A", "B", "G", "R", "Z", "orb.sum.A.hi", "orb.sum.A.lo", "orb.sum.B.hi",
                                            "orb.sum.B.lo", "orb.sum.G.hi", "orb.sum.G.lo", "orb.sum.R.hi",
                                            "orb.sum.R.lo"}));
    EXPECT_EQ(file.header().typedAttribute<Imf::IntAttribute>("orb:exactSums").value(), kExactSumsEncoding);
    ExrWriteOptions half = options;
    half.half = true;
    EXPECT_THROW(write_film_exr(scratch_path("half.exr"), synthetic_film(kWidth, kHeight, 3), synthetic_metadata(), half),
                 std::invalid_argument);
}

// Exact sums that do not give the stored values (an image edited after it
// was written, keeping the hidden channels) are refused: continuing them
// would continue another image than the one the file shows.
TEST(FilmExrRead, ExactSumsThatDisagreeWithTheImageAreRefused) {
    const std::string path = scratch_path("edited.exr");
    ExrWriteOptions options;
    options.passes = {Pass::Beauty};
    options.exact_sums = true;
    auto film = synthetic_film(kWidth, kHeight, 3);
    write_film_exr(path, film, synthetic_metadata(), options);
    // The same file with one sum changed: its R no longer matches.
    const auto edited_sums = [&] {
        orb::Film other = film;
        other.radiance[3 * 10] += 1000;
        return other;
    }();
    const std::string other_path = scratch_path("other.exr");
    write_film_exr(other_path, edited_sums, synthetic_metadata(), options);
    // Splice: the other file's exact sums of R with this file's R.
    auto raw = orb::exr::testing::read_raw_exr(path);
    const auto other_raw = orb::exr::testing::read_raw_exr(other_path);
    raw.uints.at("orb.sum.R.lo") = other_raw.uints.at("orb.sum.R.lo");
    raw.uints.at("orb.sum.R.hi") = other_raw.uints.at("orb.sum.R.hi");
    const std::string spliced = scratch_path("spliced.exr");
    orb::exr::testing::write_raw_exr(spliced, raw);
    const std::string message = message_of([&] { read_film_exr(spliced); });
    EXPECT_NE(message.find("do not give channel R at pixel (2, 1)"), std::string::npos) << message;
}

TEST(FilmExrRead, ExactSumsOfALaterEncodingAreRefused) {
    const std::string path = scratch_path("later.exr");
    ExrWriteOptions options;
    options.exact_sums = true;
    options.passes = {Pass::Beauty};
    write_film_exr(path, synthetic_film(kWidth, kHeight, 3), synthetic_metadata(), options);
    auto raw = orb::exr::testing::read_raw_exr(path);
    raw.int_attributes["orb:exactSums"] = kExactSumsEncoding + 1;
    const std::string later = scratch_path("later2.exr");
    orb::exr::testing::write_raw_exr(later, raw);
    const std::string message = message_of([&] { read_film_exr(later); });
    EXPECT_NE(message.find("orb:exactSums 2 is an encoding of exact sums this Orb does not read"), std::string::npos)
        << message;
}

// With the samples layer (adaptive sampling) every mean is over its pixel's
// own count, and the sums and counts come back.
TEST(FilmExr, PerPixelCountsNormaliseEachPixelAndComeBack) {
    // Sums made for 40 samples stay a valid set (sum of squares x n >= sum^2) over more.
    auto film = synthetic_film(kWidth, kHeight, 40);
    film.samples_per_pixel = 64;
    film.sample_ranges = orb::SampleRanges(orb::SampleRange{0, 64});
    for (std::size_t i = 0; i < film.sample_count.size(); ++i) film.sample_count[i] = static_cast<orb::film::Sum>(40 + i % 25);
    const std::string path = scratch_path("film.exr");
    ExrWriteOptions options;
    options.passes = parse_passes("beauty,normal,variance,samples");
    write_film_exr(path, film, synthetic_metadata(), options);
    const ExrFilm back = read_film_exr(path);
    EXPECT_EQ(back.film.sample_count, film.sample_count);
    expect_sums_near(film.radiance, back.film.radiance, "radiance");
    expect_sums_near(film.normal, back.film.normal, "normal");
    expect_sums_near(film.radiance_sq, back.film.radiance_sq, "radiance_sq", 16);
    // The stored mean is the sum over the pixel's count, not over orb:spp.
    const orb::exr::testing::RawExr raw = orb::exr::testing::read_raw_exr(path);
    const std::vector<float>& red = raw.channels.at("R");
    for (std::size_t i = 0; i < red.size(); ++i)
        ASSERT_FLOAT_EQ(red[i], static_cast<float>(value_of(film.radiance[i * 3]) / static_cast<double>(film.sample_count[i])))
            << i;
}

TEST(FilmExr, RoundTripKeepsEveryAttribute) {
    const auto film = synthetic_film(kWidth, kHeight, 5);
    const auto metadata = synthetic_metadata();
    const std::string path = scratch_path("film.exr");
    write_film_exr(path, film, metadata, {});
    const ExrMetadata back = read_film_exr(path).metadata;
    EXPECT_EQ(back.target_spp, metadata.target_spp);
    EXPECT_EQ(back.seed, metadata.seed);
    EXPECT_EQ(back.max_depth, metadata.max_depth);
    EXPECT_EQ(back.mode, metadata.mode);
    EXPECT_EQ(back.device, metadata.device);
    EXPECT_EQ(back.render_seconds, metadata.render_seconds);
    EXPECT_EQ(back.scene_file, metadata.scene_file);
    EXPECT_EQ(back.scene_hash, metadata.scene_hash);
    EXPECT_EQ(back.version, metadata.version);
    EXPECT_EQ(back.scene_time, metadata.scene_time);
    EXPECT_EQ(back.kernel, metadata.kernel);
    EXPECT_EQ(back.world_to_camera, metadata.world_to_camera);
    EXPECT_EQ(back.world_to_ndc, metadata.world_to_ndc);
}

TEST(FilmExr, AFilmOfUnknownKernelsWritesNoKernelAndReadsBackEmpty) {
    ExrMetadata metadata = synthetic_metadata();
    metadata.kernel.clear();
    const std::string path = scratch_path("film.exr");
    write_film_exr(path, synthetic_film(kWidth, kHeight, 2), metadata, {});
    EXPECT_EQ(Imf::InputFile(path.c_str()).header().findTypedAttribute<Imf::StringAttribute>("orb:kernel"), nullptr);
    EXPECT_EQ(read_film_exr(path).metadata.kernel, "");
}

TEST(FilmExr, WritesExactlyTheDocumentedChannelsAndAttributes) {
    const std::string path = scratch_path("film.exr");
    write_film_exr(path, synthetic_film(kWidth, kHeight, 3), synthetic_metadata(), {});
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();

    std::set<std::string> names;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        names.insert(it.name());
        EXPECT_EQ(it.channel().type, Imf::FLOAT) << it.name();
    }
    const std::set<std::string> expected{"R",          "G",          "B",          "A",
                                         "direct.R",   "direct.G",   "direct.B",   "indirect.R",
                                         "indirect.G", "indirect.B", "emission.R", "emission.G",
                                         "emission.B", "albedo.R",   "albedo.G",   "albedo.B",
                                         "N.X",        "N.Y",        "N.Z",        "orb.normalLength",
                                         "Z",          "variance.R", "variance.G", "variance.B",
                                         "id",         "background.R", "background.G", "background.B"};
    EXPECT_EQ(names, expected);

    EXPECT_EQ(header.typedAttribute<Imf::IntAttribute>("orb:spp").value(), 3);
    EXPECT_EQ(header.typedAttribute<Imf::IntAttribute>("orb:targetSpp").value(), 64);
    EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("orb:seed").value(), "18446744073709551557");
    EXPECT_EQ(header.typedAttribute<Imf::IntAttribute>("orb:maxDepth").value(), 6);
    EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("orb:mode").value(), "direct");
    EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("orb:device").value(), "Test Device (Test Platform)");
    EXPECT_EQ(header.typedAttribute<Imf::DoubleAttribute>("orb:renderSeconds").value(), 12.5);
    EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("orb:sceneFile").value(), "scenes/cornell.json");
    EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("orb:sceneHash").value(), "0123456789abcdef");
    EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("orb:version").value(), "0.1.0");
    EXPECT_EQ(header.typedAttribute<Imf::DoubleAttribute>("orb:sceneTime").value(), 0.25);
    EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("orb:kernel").value(), "5f3a9c0e1d2b4a68");
    EXPECT_EQ(header.typedAttribute<Imf::StringAttribute>("orb:passes").value(),
              "beauty,direct,indirect,emission,albedo,normal,depth,variance,id,background");
    EXPECT_EQ(header.typedAttribute<Imf::IntAttribute>("orb:filmFormat").value(), kFilmFormatVersion);
    EXPECT_TRUE(Imf::hasWorldToCamera(header));
    EXPECT_TRUE(Imf::hasWorldToNDC(header));
}

TEST(FilmExr, StoresMeansVarianceOfTheMeanAndUnitNormals) {
    const std::uint64_t n = 9;
    const auto film = synthetic_film(kWidth, kHeight, n);
    const std::string path = scratch_path("film.exr");
    write_film_exr(path, film, synthetic_metadata(), {});
    auto channels = read_channels(path);

    const char* rgb[3] = {"R", "G", "B"};
    const char* var[3] = {"variance.R", "variance.G", "variance.B"};
    for (std::size_t i = 0; i < film.pixel_count(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const double mean = value_of(film.radiance[i * 3 + c]) / n;
            EXPECT_TRUE(within_float_rounding(channels[rgb[c]][i], mean, 1)) << i;
            const double sample_variance = (value_of(film.radiance_sq[i * 3 + c]) / n - mean * mean) * n / (n - 1);
            EXPECT_TRUE(within_float_rounding(channels[var[c]][i], sample_variance / n, 8))
                << i << ": " << channels[var[c]][i] << " vs " << sample_variance / n;
        }
        EXPECT_TRUE(within_float_rounding(channels["A"][i], static_cast<double>(film.alpha[i]) / n, 1));
        const double nx = channels["N.X"][i], ny = channels["N.Y"][i], nz = channels["N.Z"][i];
        const double length = std::sqrt(nx * nx + ny * ny + nz * nz);
        if (film.normal[i * 3] != 0 || film.normal[i * 3 + 1] != 0 || film.normal[i * 3 + 2] != 0)
            EXPECT_NEAR(length, 1.0, 1e-6) << i;
        else
            EXPECT_EQ(length, 0.0) << i;
        EXPECT_EQ(channels["Z"][i], film.depth[i]);
        EXPECT_EQ(channels["id"][i], film.object_id[i]);
    }
}

TEST(FilmExr, DirectIndirectAndEmissionAddUpToBeautyInTheFile) {
    const std::string path = scratch_path("film.exr");
    write_film_exr(path, synthetic_film(kWidth, kHeight, 16), synthetic_metadata(), {});
    auto ch = read_channels(path);
    const char* suffix[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        const std::string s = suffix[c];
        for (std::size_t i = 0; i < ch[s].size(); ++i) {
            const double parts = double(ch["direct." + s][i]) + ch["indirect." + s][i] + ch["emission." + s][i];
            EXPECT_TRUE(within_float_rounding(ch[s][i], parts, 4)) << s << i;
        }
    }
}

TEST(FilmExr, HalfStoresColourAsHalfButDepthIdAndHelpersAsFloat) {
    const auto film = synthetic_film(kWidth, kHeight, 4);
    const std::string path = scratch_path("half.exr");
    ExrWriteOptions options;
    options.half = true;
    write_film_exr(path, film, synthetic_metadata(), options);
    {
        Imf::InputFile file(path.c_str());
        for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) {
            const std::string name = it.name();
            const bool float_kept = name == "Z" || name == "id" || name == "orb.normalLength";
            EXPECT_EQ(it.channel().type, float_kept ? Imf::FLOAT : Imf::HALF) << name;
        }
    }
    const ExrFilm back = read_film_exr(path);
    EXPECT_TRUE(back.half);
    for (std::size_t i = 0; i < film.radiance.size(); ++i)  // half keeps 11 significant bits
        EXPECT_NEAR(value_of(back.film.radiance[i]), value_of(film.radiance[i]), 1e-3 * value_of(film.radiance[i]) + 1e-6)
            << i;
    EXPECT_EQ(back.film.depth, film.depth);
    EXPECT_NE(message_of([&] { require_resumable(back, back.passes, path); }).find("--half"), std::string::npos);
}

TEST(FilmExr, WritesOnlyTheChosenPasses) {
    const std::string path = scratch_path("some.exr");
    ExrWriteOptions options;
    options.passes = {Pass::Beauty, Pass::Depth};
    write_film_exr(path, synthetic_film(kWidth, kHeight, 2), synthetic_metadata(), options);
    auto channels = read_channels(path);
    std::set<std::string> names;
    for (auto& [name, values] : channels) names.insert(name);
    EXPECT_EQ(names, (std::set<std::string>{"A", "B", "G", "R", "Z"}));
    const ExrFilm back = read_film_exr(path);
    EXPECT_EQ(back.passes, options.passes);
    EXPECT_NO_THROW(require_resumable(back, {Pass::Beauty}, path));
    EXPECT_NE(message_of([&] { require_resumable(back, {Pass::Albedo}, path); }).find("no albedo pass"),
              std::string::npos);
}

TEST(FilmExr, VarianceCannotBeContinuedWithoutBeauty) {
    const std::string path = scratch_path("variance.exr");
    ExrWriteOptions options;
    options.passes = {Pass::Variance};
    write_film_exr(path, synthetic_film(kWidth, kHeight, 2), synthetic_metadata(), options);
    const ExrFilm back = read_film_exr(path);
    EXPECT_NE(message_of([&] { require_resumable(back, {Pass::Variance}, path); }).find("beauty"), std::string::npos);
}

TEST(FilmExr, OneSampleRecoversSumOfSquaresExactly) {
    const auto film = synthetic_film(kWidth, kHeight, 1);
    const std::string path = scratch_path("one.exr");
    write_film_exr(path, film, synthetic_metadata(), {});
    const ExrFilm back = read_film_exr(path);
    // With one sample sum_sq is the square of the sum (the synthetic film's
    // sum_sq is not, so compare with what one sample implies).
    for (std::size_t i = 0; i < film.radiance.size(); ++i) {
        const double square = value_of(film.radiance[i]) * value_of(film.radiance[i]);
        const double back_sq = value_of(back.film.radiance_sq[i]);
        EXPECT_TRUE(std::fabs(back_sq - square) <= 0x1p-24 || within_float_rounding(back_sq, square, 2)) << i;
    }
}

TEST(FilmExr, RefusesAFilmWithoutSamples) {
    orb::Film film;
    film.resize(4, 4);
    EXPECT_THROW(write_film_exr(scratch_path("empty.exr"), film, synthetic_metadata(), {}), std::invalid_argument);
}

TEST(FilmExrRead, MissingFileIsAClearInputError) {
    const std::string path = scratch_path("nothing-here.exr");
    EXPECT_NE(message_of([&] { read_film_exr(path); }).find(path + ": no such file"), std::string::npos);
}

TEST(FilmExrRead, NonExrFileIsAClearInputError) {
    const std::string path = scratch_path("text.exr");
    std::ofstream(path) << "{\"not\": \"an image\"}\n";
    EXPECT_NE(message_of([&] { read_film_exr(path); }).find("not an OpenEXR file"), std::string::npos);
}

TEST(FilmExrRead, ForeignExrIsRefusedAsNotAnOrbRender) {
    const std::string path = scratch_path("foreign.exr");
    {
        std::vector<Imf::Rgba> pixels(16, Imf::Rgba(0.5f, 0.5f, 0.5f, 1.0f));
        Imf::RgbaOutputFile file(path.c_str(), 4, 4, Imf::WRITE_RGBA);
        file.setFrameBuffer(pixels.data(), 1, 4);
        file.writePixels(4);
    }
    EXPECT_NE(message_of([&] { read_film_exr(path); }).find("not an orb-render image"), std::string::npos);
}

TEST(FilmExrRead, TruncatedFileIsAClearInputError) {
    const std::string path = scratch_path("cut.exr");
    ExrWriteOptions options;
    options.compression = ExrCompression::None;
    write_film_exr(path, synthetic_film(64, 48, 2), synthetic_metadata(), options);
    const auto size = std::filesystem::file_size(path);
    std::filesystem::resize_file(path, size / 2);
    const std::string message = message_of([&] { read_film_exr(path); });
    EXPECT_NE(message.find(path + ": "), std::string::npos) << message;
    EXPECT_NE(message.find("truncated"), std::string::npos) << message;
}

TEST(FilmExrRead, HeaderOnlyFragmentIsAClearInputError) {
    const std::string path = scratch_path("fragment.exr");
    write_film_exr(path, synthetic_film(kWidth, kHeight, 2), synthetic_metadata(), {});
    std::filesystem::resize_file(path, 200);
    EXPECT_NE(message_of([&] { read_film_exr(path); }).find(path + ": "), std::string::npos);
}

// NONE, ZIPS and ZIP go through Orb's own block writer (libdeflate, blocks
// filled on every core), RLE and PIZ through OpenEXR's C++ writer: every
// kind stores the same values, for sizes whose last block is short (ZIP's 16
// rows do not divide 37), one-pixel-wide images and HALF storage.
TEST(FilmExr, EveryCompressionStoresTheSameValues) {
    for (const auto& [width, height] : {std::pair{97, 37}, std::pair{1, 19}, std::pair{300, 1}}) {
        for (const bool half : {false, true}) {
            const orb::Film film = synthetic_film(width, height, 5, 7);
            ExrWriteOptions options;
            options.half = half;
            options.compression = ExrCompression::Piz;
            const std::string reference_path = scratch_path("piz.exr");
            write_film_exr(reference_path, film, synthetic_metadata(), options);
            const auto reference = read_channels(reference_path);
            for (const ExrCompression kind : {ExrCompression::None, ExrCompression::Rle, ExrCompression::Zips,
                                              ExrCompression::Zip}) {
                options.compression = kind;
                const std::string path = scratch_path(std::string(compression_name(kind)) + ".exr");
                write_film_exr(path, film, synthetic_metadata(), options);
                const std::string what = std::string(compression_name(kind)) + " " + std::to_string(width) + "x" +
                                         std::to_string(height) + (half ? " half" : "");
                EXPECT_EQ(read_channels(path), reference) << what;
                Imf::InputFile file(path.c_str());
                EXPECT_EQ(file.header().compression(), kind == ExrCompression::None   ? Imf::NO_COMPRESSION
                                                       : kind == ExrCompression::Rle  ? Imf::RLE_COMPRESSION
                                                       : kind == ExrCompression::Zips ? Imf::ZIPS_COMPRESSION
                                                                                      : Imf::ZIP_COMPRESSION)
                    << what;
                // And back into the film's sums, as --resume does.
                if (!half) expect_sums_near(film.radiance, read_film_exr(path).film.radiance, what.c_str());
            }
        }
    }
}

// A reused encoding (as the frame writer keeps one per thread) writes each
// film whole, whatever it wrote before.
TEST(FilmExr, AReusedEncodingWritesEachFilmWhole) {
    ExrEncoding encoding;
    ExrWriteOptions options;
    const orb::Film big = synthetic_film(64, 48, 3, 1), small = synthetic_film(8, 6, 2, 2);
    encode_film_exr(big, synthetic_metadata(), options, encoding);
    encode_film_exr(small, synthetic_metadata(), options, encoding);
    const std::string again(encoding.bytes());
    EXPECT_EQ(again, encode_film_exr(small, synthetic_metadata(), options));
}
