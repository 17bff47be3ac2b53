// A render that cannot fit the memory it may use stops before any driver is
// asked for it, with one message saying how much it needs and how much
// there is, and leaves nothing behind (no output, lock or temporary file):
// an allocation failing inside PoCL ends the process on the spot instead.
#include "cli_fixture.h"

using namespace orb::test;

TEST_F(RenderCli, ARenderThatCannotFitTheMemoryLimitSaysSoAndLeavesNothing) {
    const std::string scene = write_scene(small_scene());
    // 8192x8192 with every layer: a film of 14 GB, under a limit of 2.9 GB of address space.
    const auto run = run_process({"/bin/bash", "-c",
                                  "ulimit -v 3000000 && exec \"$0\" \"$@\"", render_exe(), scene, "--width", "8192",
                                  "--height", "8192", "--passes", "all", "--spp", "1", "-o", path("x.exr")});
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_NE(run.err.find("orb-render: error: not enough memory: needs "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(", has "), std::string::npos) << run.err;
    EXPECT_EQ(files(), (std::vector<std::string>{"scene.json"}));
}
