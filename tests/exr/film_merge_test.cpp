// merge_films: slices of one render add up to the same bits, in any order of
// the inputs and any grouping of merges.
#include <gtest/gtest.h>

#include "orb/exr/film_merge.h"
#include "orb/scene/error.h"
#include "test_film.h"

using namespace orb::exr;
using orb::exr::testing::synthetic_film;
using orb::exr::testing::synthetic_metadata;

namespace {

MergeInput slice(const char* name, const char* ranges, unsigned seed) {
    const auto parsed = orb::SampleRanges::parse(ranges);
    ExrFilm file;
    file.film = synthetic_film(5, 4, parsed.total(), seed);
    file.film.sample_ranges = parsed;
    file.metadata = synthetic_metadata();
    file.metadata.target_spp = parsed.total();
    file.metadata.render_seconds = 1.5;
    file.metadata.device = name;
    file.passes = all_passes();
    file.exact = true;
    return {name, file};
}

}  // namespace

TEST(FilmMerge, SlicesAddUpWhateverTheOrderOfTheInputs) {
    const MergeInput a = slice("a", "0:3", 1), b = slice("b", "3:5", 2), c = slice("c", "8:2", 3);
    const ExrFilm forward = merge_films({a, b, c});
    const ExrFilm shuffled = merge_films({c, a, b});
    EXPECT_EQ(forward.film.samples_per_pixel, 10u);
    EXPECT_EQ(forward.film.sample_ranges.format(), "0:10");
    // Integer sums: the very same bits in any order, and in any grouping.
    EXPECT_EQ(forward.film.radiance, shuffled.film.radiance);
    EXPECT_EQ(forward.film.radiance_sq, shuffled.film.radiance_sq);
    for (std::size_t i = 0; i < forward.film.radiance.size(); ++i)
        EXPECT_EQ(forward.film.radiance[i], a.file.film.radiance[i] + b.file.film.radiance[i] + c.file.film.radiance[i]);
    const ExrFilm bc = merge_films({b, c});
    const ExrFilm grouped = merge_films({MergeInput{"bc", bc}, a});
    EXPECT_EQ(grouped.film.radiance, forward.film.radiance);
    EXPECT_EQ(grouped.film.normal, forward.film.normal);
    EXPECT_EQ(grouped.film.sample_ranges, forward.film.sample_ranges);
    EXPECT_TRUE(grouped.exact);
    // The centre-ray channels come from the slice holding sample 0.
    EXPECT_EQ(shuffled.film.depth, a.file.film.depth);
    EXPECT_EQ(shuffled.film.object_id, a.file.film.object_id);
    EXPECT_EQ(forward.metadata.target_spp, 10u);
    EXPECT_EQ(forward.metadata.render_seconds, 4.5);
    EXPECT_EQ(shuffled.metadata.device, "a; b; c");
}

TEST(FilmMerge, AMergeIsExactOnlyWhenEveryInputWas) {
    MergeInput means_only = slice("b", "3:5", 2);
    means_only.file.exact = false;
    EXPECT_TRUE(merge_films({slice("a", "0:3", 1), slice("b", "3:5", 2)}).exact);
    EXPECT_FALSE(merge_films({slice("a", "0:3", 1), means_only}).exact);
}

TEST(FilmMerge, RefusesTheSamplesOfOtherKernelsNamingBothFiles) {
    MergeInput other = slice("other.exr", "3:2", 2);
    other.file.metadata.kernel = "9a0b1c2d3e4f5061";
    try {
        merge_films({slice("a.exr", "0:3", 1), other});
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "other.exr: orb:kernel 9a0b1c2d3e4f5061 differs from a.exr's 5f3a9c0e1d2b4a68; only slices of the "
                  "same render merge");
    }
    // A file that does not say (an older Orb's) is not taken for one that does.
    MergeInput unnamed = slice("old.exr", "3:2", 2);
    unnamed.file.metadata.kernel.clear();
    try {
        merge_films({slice("a.exr", "0:3", 1), unnamed});
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "old.exr: orb:kernel (none) differs from a.exr's 5f3a9c0e1d2b4a68; only slices of the same render "
                  "merge");
    }
}

TEST(FilmMerge, NamesTheFileThatDiffersOrOverlaps) {
    MergeInput other = slice("other.exr", "3:2", 2);
    other.file.metadata.scene_hash = "fedcba9876543210";
    try {
        merge_films({slice("a.exr", "0:3", 1), other});
        FAIL() << "expected an error";
    } catch (const orb::InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "other.exr: orb:sceneHash fedcba9876543210 differs from a.exr's 0123456789abcdef; only slices of "
                  "the same render merge");
    }
    EXPECT_THROW(merge_films({slice("a.exr", "0:3", 1), slice("b.exr", "2:3", 1)}), orb::InputError);
    MergeInput half = slice("half.exr", "3:2", 2);
    half.file.half = true;
    EXPECT_THROW(merge_films({slice("a.exr", "0:3", 1), half}), orb::InputError);
}
