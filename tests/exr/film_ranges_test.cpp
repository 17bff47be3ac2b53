// The sample indices a film holds travel in orb:sampleRanges; files of film
// format 1, from before slices existed, hold the first orb:spp samples.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <list>

#include "orb/exr/film_exr.h"
#include "orb/scene/error.h"
#include "test_film.h"

using namespace orb::exr;
using orb::exr::testing::message_of;
using orb::exr::testing::scratch_path;
using orb::exr::testing::synthetic_film;
using orb::exr::testing::synthetic_metadata;

namespace {

// Copies an EXR with `edit` applied to its header (every channel as FLOAT).
void rewrite(const std::string& from, const std::string& to, const std::function<void(Imf::Header&)>& edit) {
    Imf::InputFile in(from.c_str());
    Imf::Header header = in.header();
    const auto window = header.dataWindow();
    const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    Imf::FrameBuffer frame;
    std::list<std::vector<float>> planes;
    Imf::ChannelList channels;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        auto& values = planes.emplace_back(static_cast<std::size_t>(width) * height);
        frame.insert(it.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()), sizeof(float),
                                           sizeof(float) * width));
        channels.insert(it.name(), Imf::Channel(Imf::FLOAT));
    }
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    header.channels() = channels;
    edit(header);
    Imf::OutputFile out(to.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(height);
}

orb::Film film_of(const char* ranges) {
    const auto parsed = orb::SampleRanges::parse(ranges);
    orb::Film film = synthetic_film(4, 3, parsed.total());
    film.sample_ranges = parsed;
    return film;
}

}  // namespace

TEST(FilmRanges, TheRangesTravelWithTheFile) {
    const std::string path = scratch_path("slices.exr");
    write_film_exr(path, film_of("40:3,16:4"), synthetic_metadata(), {});
    Imf::InputFile file(path.c_str());
    EXPECT_EQ(file.header().typedAttribute<Imf::StringAttribute>("orb:sampleRanges").value(), "16:4,40:3");
    const ExrFilm back = read_film_exr(path);
    EXPECT_EQ(back.film.samples_per_pixel, 7u);
    EXPECT_EQ(back.film.sample_ranges.format(), "16:4,40:3");
}

TEST(FilmRanges, AFilmThatSetsOnlyItsCountIsWrittenAsTheFirstSamples) {
    const std::string path = scratch_path("count.exr");
    write_film_exr(path, synthetic_film(4, 3, 5), synthetic_metadata(), {});
    EXPECT_EQ(read_film_exr(path).film.sample_ranges.format(), "0:5");
}

TEST(FilmRanges, AFormat1FileHoldsTheFirstSamples) {
    const std::string v2 = scratch_path("v2.exr"), v1 = scratch_path("v1.exr");
    write_film_exr(v2, film_of("0:6"), synthetic_metadata(), {});
    rewrite(v2, v1, [](Imf::Header& header) {
        header.erase("orb:sampleRanges");
        header.insert("orb:filmFormat", Imf::IntAttribute(1));
    });
    const ExrFilm back = read_film_exr(v1);
    EXPECT_EQ(back.film.sample_ranges.format(), "0:6");
    EXPECT_EQ(back.film.radiance, read_film_exr(v2).film.radiance);
}

TEST(FilmRanges, MissingOrInconsistentRangesAndUnknownFormatsAreRefused) {
    const std::string good = scratch_path("good.exr"), bad = scratch_path("bad.exr");
    write_film_exr(good, film_of("0:6"), synthetic_metadata(), {});

    rewrite(good, bad, [](Imf::Header& header) { header.erase("orb:sampleRanges"); });
    EXPECT_NE(message_of([&] { read_film_exr(bad); }).find("orb:sampleRanges"), std::string::npos);

    rewrite(good, bad, [](Imf::Header& header) { header.insert("orb:sampleRanges", Imf::StringAttribute("0:5")); });
    EXPECT_NE(message_of([&] { read_film_exr(bad); }).find("holds 5 samples per pixel but orb:spp is 6"),
              std::string::npos);

    rewrite(good, bad, [](Imf::Header& header) { header.insert("orb:sampleRanges", Imf::StringAttribute("0:4,2:2")); });
    EXPECT_NE(message_of([&] { read_film_exr(bad); }).find("overlaps"), std::string::npos);

    rewrite(good, bad, [](Imf::Header& header) { header.insert("orb:filmFormat", Imf::IntAttribute(3)); });
    EXPECT_NE(message_of([&] { read_film_exr(bad); }).find("film format 3"), std::string::npos);
}

TEST(FilmSummary, TellsAFinishedFileFromOneCutShort) {
    const std::string path = scratch_path("frame.exr");
    write_film_exr(path, film_of("0:6"), synthetic_metadata(), {});
    const ExrFilmSummary summary = read_film_exr_summary(path);
    EXPECT_EQ(summary.samples_per_pixel, 6u);
    EXPECT_EQ(summary.metadata.target_spp, 64u);
    EXPECT_EQ(summary.sample_ranges.format(), "0:6");
    EXPECT_EQ(summary.width, 4);
    std::filesystem::resize_file(path, std::filesystem::file_size(path) - 100);
    EXPECT_THROW(read_film_exr_summary(path), orb::InputError);
}
