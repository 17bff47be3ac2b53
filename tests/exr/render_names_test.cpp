// The names of the integrator modes and samplers (orb/tables/render_names.h),
// one table each for the command line, the film's header and the renderer.
#include <gtest/gtest.h>

#include "orb/exr/film_exr.h"
#include "orb/tables/render_names.h"
#include "test_film.h"

using namespace orb::device;

TEST(RenderNames, EveryValueHasOneNameThatNamesItBack) {
    for (const auto& row : kIntegratorModeNames) {
        EXPECT_EQ(name_in(kIntegratorModeNames, row.value), row.name);
        EXPECT_EQ(value_in(kIntegratorModeNames, row.name), row.value);
    }
    for (const auto& row : kSamplerNames) {
        EXPECT_EQ(name_in(kSamplerNames, row.value), row.name);
        EXPECT_EQ(value_in(kSamplerNames, row.name), row.value);
    }
    EXPECT_EQ(value_in(kIntegratorModeNames, "Global"), std::nullopt);  // names are exact
    EXPECT_EQ(value_in(kSamplerNames, ""), std::nullopt);
    EXPECT_EQ(names_in(kIntegratorModeNames), (std::vector<std::string>{"global", "direct"}));
    EXPECT_EQ(names_in(kSamplerNames), (std::vector<std::string>{"sobol", "independent"}));
    EXPECT_EQ(choices_in(kIntegratorModeNames), "global or direct");
    EXPECT_EQ(choices_in(kSamplerNames), "sobol or independent");
}

TEST(RenderNames, TheFilmsHeaderIsReadAgainstTheTables) {
    EXPECT_EQ(orb::exr::ExrMetadata{}.sampler, "sobol");  // the first row: the default
    orb::exr::ExrMetadata bad = orb::exr::testing::synthetic_metadata();
    bad.mode = "bidirectional";
    const std::string path = orb::exr::testing::scratch_path("bad-mode.exr");
    orb::exr::write_film_exr(path, orb::exr::testing::synthetic_film(4, 3, 2), bad, {});
    try {
        orb::exr::read_film_exr(path);
        FAIL() << "expected an error";
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("orb:mode must be global or direct, got 'bidirectional'"), std::string::npos)
            << e.what();
    }
}
