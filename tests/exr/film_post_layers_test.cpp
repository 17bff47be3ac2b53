// Post layers (the denoised layer) written by the film's one encode: every
// film channel as without them, the layer's channels from the values the file
// stores, its attributes, with every compression and under --half.
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <gtest/gtest.h>

#include <Imath/half.h>

#include <fstream>
#include <stdexcept>

#include "exr_channels.h"
#include "orb/exr/film_exr.h"
#include "orb/scene/error.h"
#include "test_film.h"

using namespace orb::exr;
using orb::exr::testing::RawExr;
using orb::exr::testing::read_raw_exr;
using orb::exr::testing::scratch_path;
using orb::exr::testing::synthetic_film;
using orb::exr::testing::synthetic_metadata;

namespace {

void write_bytes(const std::string& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// A layer whose values are twice the stored beauty, read through StoredImage.
PostLayerPlanes doubled_beauty() {
    PostLayerPlanes layer;
    layer.layer = orb::film::PostLayer::Denoised;
    layer.attributes = {{"orb:denoised", "twice the beauty"}};
    layer.compute = [](const StoredImage& image, std::span<const std::span<float>> out) {
        const std::size_t pixels = static_cast<std::size_t>(image.width()) * static_cast<std::size_t>(image.height());
        if (out.size() != 3) throw std::logic_error("the denoised layer has three channels");
        const char* names[3] = {"R", "G", "B"};
        for (std::size_t c = 0; c < 3; ++c) {
            const StoredImage::Channel* channel = image.find(names[c]);
            if (!channel) throw std::logic_error("no beauty");
            if (out[c].size() != pixels) throw std::logic_error("a channel of the wrong size");
            for (std::size_t i = 0; i < pixels; ++i) out[c][i] = 2 * StoredImage::value(*channel, i);
        }
    };
    return layer;
}

}  // namespace

TEST(FilmPostLayers, WrittenBesideTheFilmFromTheStoredValues) {
    const orb::Film film = synthetic_film(97, 37, 5, 3);
    const std::vector<PostLayerPlanes> post{doubled_beauty()};
    for (const ExrCompression kind : {ExrCompression::None, ExrCompression::Rle, ExrCompression::Zips,
                                      ExrCompression::Zip, ExrCompression::Piz}) {
        for (const bool half : {false, true}) {
            const std::string what = std::string(compression_name(kind)) + (half ? " half" : "");
            ExrWriteOptions options;
            options.compression = kind;
            options.half = half;
            const std::string plain_path = scratch_path("plain.exr"), post_path = scratch_path("post.exr");
            write_bytes(plain_path, encode_film_exr(film, synthetic_metadata(), options));
            write_bytes(post_path, encode_film_exr(film, synthetic_metadata(), options, post));
            const RawExr plain = read_raw_exr(plain_path);
            RawExr with_post = read_raw_exr(post_path);

            for (const char* name : {"denoised.R", "denoised.G", "denoised.B"}) {
                ASSERT_EQ(with_post.channels.count(name), 1u) << what << " " << name;
                EXPECT_EQ(with_post.channel_types.at(name), half ? "HALF" : "FLOAT") << what << " " << name;
                const std::vector<float>& beauty = plain.channels.at(std::string(1, name[9]));
                const std::vector<float>& layer = with_post.channels.at(name);
                ASSERT_EQ(layer.size(), beauty.size());
                for (std::size_t i = 0; i < layer.size(); ++i) {
                    // The file's beauty doubled, stored as the file stores colour.
                    const float expected = half ? static_cast<float>(Imath::half(2 * beauty[i])) : 2 * beauty[i];
                    ASSERT_EQ(layer[i], expected) << what << " " << name << "[" << i << "]";
                }
                with_post.channels.erase(name);
                with_post.channel_types.erase(name);
            }
            // Every other channel as the encode without the layer wrote it.
            EXPECT_EQ(with_post.channels, plain.channels) << what;
            EXPECT_EQ(with_post.channel_types, plain.channel_types) << what;
            Imf::InputFile file(post_path.c_str());
            const auto* attribute = file.header().findTypedAttribute<Imf::StringAttribute>("orb:denoised");
            ASSERT_NE(attribute, nullptr) << what;
            EXPECT_EQ(attribute->value(), "twice the beauty") << what;
            with_post.attribute_types.erase("orb:denoised");
            EXPECT_EQ(with_post.attribute_types, plain.attribute_types) << what;
        }
    }
}

// A frame loop reuses one encoding: a frame without the layer has none.
TEST(FilmPostLayers, AReusedEncodingWritesThemOnlyWhenAsked) {
    ExrEncoding encoding;
    const orb::Film film = synthetic_film(16, 9, 2, 4);
    const std::vector<PostLayerPlanes> post{doubled_beauty()};
    encode_film_exr(film, synthetic_metadata(), ExrWriteOptions{}, encoding, post);
    EXPECT_NE(std::string(encoding.bytes()), encode_film_exr(film, synthetic_metadata(), ExrWriteOptions{}));
    encode_film_exr(film, synthetic_metadata(), ExrWriteOptions{}, encoding);
    EXPECT_EQ(std::string(encoding.bytes()), encode_film_exr(film, synthetic_metadata(), ExrWriteOptions{}));
    encode_film_exr(film, synthetic_metadata(), ExrWriteOptions{}, encoding, post);
    EXPECT_EQ(std::string(encoding.bytes()), encode_film_exr(film, synthetic_metadata(), ExrWriteOptions{}, post));
}

TEST(FilmPostLayers, AFailingLayerIsAnError) {
    const orb::Film film = synthetic_film(8, 6, 2, 5);
    PostLayerPlanes failing = doubled_beauty();
    failing.compute = [](const StoredImage&, std::span<const std::span<float>>) { throw orb::InputError("bad pixel"); };
    EXPECT_THROW(encode_film_exr(film, synthetic_metadata(), ExrWriteOptions{}, std::vector{failing}),
                 orb::InputError);
}
