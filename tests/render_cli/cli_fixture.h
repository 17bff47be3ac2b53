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

// Two renders of the same samples (in any passes, runs, slices merged in
// any grouping, devices, load): every channel the images show is the same
// bit for bit, and so are the exact sums where both files carry them (a
// finished render has none: its other channels are what count).
void expect_same_image(const exr::testing::RawExr& a, const exr::testing::RawExr& b);
void expect_same_image(const std::string& path_a, const std::string& path_b);

// Two renders of the same samples where one was continued from a file of
// means only (a finished render, or an older Orb's): its sums were rebuilt
// from the means, so the shown channels agree within float rounding (a few
// dozen float ulps; more for the variance, whose (sum_sq/n - mean^2)
// cancels). Exact sums are not compared.
void expect_same_within_float_rounding(const exr::testing::RawExr& a, const exr::testing::RawExr& b);

// Whether a file carries its film's exact sums (orb:exactSums, orb.sum.* channels).
bool has_exact_sums(const exr::testing::RawExr& image);

}  // namespace orb::test
