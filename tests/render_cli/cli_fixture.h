// Shared set-up for the orb-render command-line tests: a scratch folder per
// test, small scenes written with the scene library, and the executable.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "exr_channels.h"
#include "orb/exr/film_exr.h"
#include "orb/scene/scene.h"
#include "process.h"

namespace orb::test {

// A small open scene: a floor, a diffuse ball, a mirror ball and a sphere
// light, seen from the front with sky (misses) at the top, so every pass has
// something in it. 32x24, 4 spp by default.
Scene small_scene();

// small_scene() with its red ball moving from x = -1.5 at t = 0 to x = 1.5 at
// t = 1 s (one node, a linear translation channel).
Scene moving_ball_scene();

class RenderCli : public ::testing::Test {
protected:
    void SetUp() override;

    std::string path(const std::string& name) const;       // inside this test's scratch folder
    std::string write_scene(const Scene& scene, const std::string& name = "scene.json") const;

    // orb-render with these arguments (stdin from /dev/null unless given).
    ProcessResult render(const std::vector<std::string>& args, const std::string& stdin_path = "",
                         const std::string& stdout_path = "") const;

    // orb-merge with these arguments.
    ProcessResult merge(const std::vector<std::string>& args) const;

    // Files in the scratch folder, to check nothing partial was left behind.
    std::vector<std::string> files() const;

    std::string dir_;
};

std::string render_exe();

// Mean-valued channels of two renders agree within float rounding: the
// relative difference allowed covers the sums' different addition order
// (resume, pass splits) and the mean*n recovery, a few dozen float ulps.
void expect_same_within_float_rounding(const exr::testing::RawExr& a, const exr::testing::RawExr& b);

// Every channel of two films of the same samples, summed in different
// groupings: equal for the pixel-centre channels (no sums), else within
// `relative_bound` of the sum of magnitudes per value (the value itself for
// the non-negative channels, n samples for normals, |component| <= 1).
// Each test derives its bound from how its films were summed.
void expect_sums_within(const exr::ExrFilm& a, const exr::ExrFilm& b, double relative_bound);

}  // namespace orb::test
