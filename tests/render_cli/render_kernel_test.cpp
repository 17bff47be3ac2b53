// orb:kernel: a film says which kernels rendered it, and one of other
// kernels is another render: --resume and --skip-existing render it again
// from its first sample (one line says why), orb-merge refuses to mix them.
// Other kernels here: a definition no kernel reads, in ORB_CL_OPTIONS.
#include <filesystem>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"
#include "process.h"

using namespace orb::test;

namespace {

constexpr const char* kOtherKernels = "ORB_CL_OPTIONS=-DORB_KERNEL_IDENTITY_TEST=1";

ProcessResult render_with_other_kernels(const std::vector<std::string>& args) {
    std::vector<std::string> argv{"/usr/bin/env", kOtherKernels, render_exe()};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_process(argv);
}

std::string kernel_of(const std::string& path) { return orb::exr::read_film_exr(path).metadata.kernel; }

}  // namespace

TEST_F(RenderCli, AFilmOfOtherKernelsIsRenderedAgainAndNotMerged) {
    const std::string scene = write_scene(small_scene());
    ASSERT_EQ(render({scene, "-o", path("whole.exr"), "--spp", "4", "--seed", "3"}).exit_code, 0);
    // Stopped short by --time, with exact sums: --resume would continue it, were its kernels these.
    const auto part = render_with_other_kernels(
        {scene, "-o", path("part.exr"), "--spp", "4", "--seed", "3", "--time", "0.000001"});
    ASSERT_EQ(part.exit_code, 0) << part.err;
    const std::string these = kernel_of(path("whole.exr")), other = kernel_of(path("part.exr"));
    ASSERT_EQ(these.size(), 16u);
    ASSERT_EQ(other.size(), 16u);
    ASSERT_NE(these, other);
    const std::string why = "rendered by other kernels (orb:kernel " + other + ", these are " + these + ")";

    const auto resumed = render({scene, "--resume", path("part.exr"), "-o", path("resumed.exr")});
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_NE(resumed.err.find(path("part.exr") + ": " + why + "; rendering it again from its first sample"),
              std::string::npos)
        << resumed.err;
    EXPECT_EQ(kernel_of(path("resumed.exr")), these);
    expect_same_image(path("whole.exr"), path("resumed.exr"));

    std::filesystem::copy_file(path("part.exr"), path("skip.exr"));
    const auto skipped = render({scene, "-o", path("skip.exr"), "--spp", "4", "--seed", "3", "--skip-existing"});
    ASSERT_EQ(skipped.exit_code, 0) << skipped.err;
    EXPECT_NE(skipped.err.find(why + ": rendering again"), std::string::npos) << skipped.err;
    expect_same_image(path("whole.exr"), path("skip.exr"));

    // Two slices of one frame, by two kernels: refused, naming both files.
    ASSERT_EQ(render({scene, "-o", path("a.exr"), "--sample-range", "0:2", "--seed", "3"}).exit_code, 0);
    const auto b = render_with_other_kernels({scene, "-o", path("b.exr"), "--sample-range", "2:2", "--seed", "3"});
    ASSERT_EQ(b.exit_code, 0) << b.err;
    const auto merged = merge({path("a.exr"), path("b.exr"), "-o", path("merged.exr")});
    EXPECT_EQ(merged.exit_code, 1);
    EXPECT_NE(merged.err.find(path("b.exr") + ": orb:kernel " + other + " differs from " + path("a.exr") + "'s " + these),
              std::string::npos)
        << merged.err;
    EXPECT_FALSE(std::filesystem::exists(path("merged.exr")));
}
