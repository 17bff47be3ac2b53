// Telling sources apart without decoding them: size, modification time in
// nanoseconds and, for orb-render EXRs, what their header says they hold.
#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/types.h>

#include <fstream>

#include "orb/image/source_identity.h"
#include "test_support.h"

using namespace orb::image;
using namespace orb::image::test;
namespace OIIO = OIIO_NAMESPACE;

namespace {

// An EXR as orb-render leaves it, as far as the identity goes.
void write_render(const std::string& path, const Image& image, int spp) {
    OIIO::ImageSpec spec(image.width, image.height, image.channels(), OIIO::TypeDesc::FLOAT);
    spec.channelnames.assign(image.channel_names.begin(), image.channel_names.end());
    spec.attribute("orb:spp", spp);
    spec.attribute("orb:sceneHash", "0123456789abcdef");
    spec.attribute("orb:seed", 7);
    spec.attribute("orb:renderSeconds", 1.5f);  // not part of the identity
    auto out = OIIO::ImageOutput::create(path);
    if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) ||
        !out->close())
        FAIL() << "cannot write " << path;
}

void set_mtime(const std::string& path, std::int64_t ns) {
    const timespec times[2] = {{ns / 1'000'000'000, ns % 1'000'000'000}, {ns / 1'000'000'000, ns % 1'000'000'000}};
    ASSERT_EQ(::utimensat(AT_FDCWD, path.c_str(), times, 0), 0);
}

}  // namespace

TEST(SourceIdentity, AFileIsItsSizeAndTime) {
    ScratchDir dir;
    const std::string path = dir.path("a.exr");
    write_exr(path, make_scene(8, 4, 2.0f));
    const SourceLookup a = identify_source(path);
    ASSERT_EQ(a.state, SourceLookup::State::File);
    EXPECT_EQ(a.identity.size, std::filesystem::file_size(path));
    EXPECT_GT(a.identity.mtime_ns, 0);
    EXPECT_TRUE(a.identity.render.empty()) << "not written by orb-render";
    EXPECT_EQ(identify_source(path).identity, a.identity) << "looking again changes nothing";

    set_mtime(path, a.identity.mtime_ns + 1);  // one nanosecond later
    EXPECT_NE(identify_source(path).identity, a.identity);
}

TEST(SourceIdentity, AnOrbRenderHeaderTellsRendersApartAtTheSameSizeAndTime) {
    ScratchDir dir;
    const std::string path = dir.path("beauty.exr");
    const Image image = make_scene(8, 4, 2.0f);
    write_render(path, image, 64);
    const SourceLookup first = identify_source(path);
    ASSERT_EQ(first.state, SourceLookup::State::File);
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"orb:sceneHash", "0123456789abcdef"}, {"orb:spp", "64"}, {"orb:seed", "7"}};
    EXPECT_EQ(first.identity.render, expected);

    // Rendered again with more samples, same size, and a clock too coarse to tell.
    write_render(path, image, 256);
    set_mtime(path, first.identity.mtime_ns);
    const SourceLookup second = identify_source(path);
    ASSERT_EQ(second.identity.size, first.identity.size);
    ASSERT_EQ(second.identity.mtime_ns, first.identity.mtime_ns);
    EXPECT_NE(second.identity, first.identity);
}

TEST(SourceIdentity, TheHeaderIsReadNotThePixels) {
    ScratchDir dir;
    const std::string path = dir.path("cut.exr");
    write_render(path, make_scene(256, 256, 2.0f, 0.5f), 16);
    // Cut off half of the pixels: decoding would fail, the header still tells what the file holds.
    const auto half = std::filesystem::file_size(path) / 2;
    std::filesystem::resize_file(path, half);
    EXPECT_THROW(read_image(path), std::exception);
    const SourceLookup cut = identify_source(path);
    ASSERT_EQ(cut.state, SourceLookup::State::File);
    EXPECT_EQ(cut.identity.size, half);
    EXPECT_FALSE(cut.identity.render.empty());
}

TEST(SourceIdentity, StreamsHaveNoIdentityAndMissingFilesAreMissing) {
    ScratchDir dir;
    EXPECT_EQ(identify_source("-").state, SourceLookup::State::NotAFile);
    const std::string fifo = dir.path("fifo");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(identify_source(fifo).state, SourceLookup::State::NotAFile) << "and opening it would block";
    EXPECT_EQ(identify_source(dir.path("")).state, SourceLookup::State::NotAFile) << "a folder";
    EXPECT_EQ(identify_source(dir.path("gone.exr")).state, SourceLookup::State::Missing);
    EXPECT_EQ(identify_source(dir.path("no/such/folder.exr")).state, SourceLookup::State::Missing);
}
