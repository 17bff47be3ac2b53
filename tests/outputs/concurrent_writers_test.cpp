// Concurrent and interrupted runs: a second writer of one output fails at
// once, SIGHUP saves the render like SIGTERM, and temporaries left by a
// killed process are removed by the next successful write.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <thread>

#include "orb/exr/film_exr.h"
#include "output_fixture.h"

namespace fs = std::filesystem;
using namespace orb::test;
using ::testing::HasSubstr;

namespace {

// A long render writing `out` with a checkpoint every 0.2 s, so that the
// file's appearance shows the render loop (and its signal handling) is on.
std::vector<std::string> long_render(const std::string& scene, const std::string& out) {
    return {tool("orb-render"), scene, "--width", "16", "--height", "12", "--spp", "100000000", "--time", "60",
            "--checkpoint", "0.2", "-o", out};
}

pid_t a_dead_pid() {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(0);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return pid;
}

}  // namespace

TEST_F(OutputSafety, ASecondWriterOfOneOutputFailsAtOnce) {
    const std::string scene = scene_file(), out = path("out.exr");
    Child first(long_render(scene, out), path("first.txt"));
    ASSERT_TRUE(eventually([&] { return fs::exists(out); }, 60)) << read_text(path("first.txt"));

    std::vector<std::string> args = tiny_render_args(scene);
    args.insert(args.end(), {"-o", out});
    const ProcessResult second = run("orb-render", args);
    EXPECT_EQ(second.exit_code, 1);
    EXPECT_THAT(second.err, HasSubstr("another process (pid "));
    EXPECT_THAT(second.err, HasSubstr("is writing this output"));
    EXPECT_THAT(second.err, ::testing::Not(HasSubstr("device: ")));

    first.send_signal(SIGTERM);
    EXPECT_EQ(first.wait(60).exit_code, 143);
    EXPECT_GE(orb::exr::read_film_exr(out).film.samples_per_pixel, 1u);
    // The lock is gone with its holder: the next writer succeeds.
    EXPECT_EQ(run("orb-render", args).exit_code, 0);
    EXPECT_EQ(files(), (std::vector<std::string>{"first.txt", "out.exr", "scene.json"}));
}

TEST_F(OutputSafety, TwoResumesOfOneFileCannotBothRun) {
    const std::string scene = scene_file(), out = path("r.exr");
    std::vector<std::string> args = tiny_render_args(scene);
    args.insert(args.end(), {"-o", out});
    ASSERT_EQ(run("orb-render", args).exit_code, 0);

    std::vector<std::string> resume{tool("orb-render"), scene, "--resume", out, "-o", out, "--spp", "100000000",
                                    "--time", "60", "--checkpoint", "0.2"};
    Child first(resume, path("first.txt"));
    ASSERT_TRUE(eventually([&] { return orb::exr::read_film_exr(out).film.samples_per_pixel > 1; }, 60))
        << read_text(path("first.txt"));
    const ProcessResult second = run("orb-render", {scene, "--resume", out, "-o", out, "--spp", "2"});
    EXPECT_EQ(second.exit_code, 1);
    EXPECT_THAT(second.err, HasSubstr("is writing this output"));

    first.send_signal(SIGINT);
    EXPECT_EQ(first.wait(60).exit_code, 130);
    EXPECT_GT(orb::exr::read_film_exr(out).film.samples_per_pixel, 1u);
}

TEST_F(OutputSafety, SighupFinishesThePassWritesAndExits129) {
    const std::string out = path("out.exr");
    Child child(long_render(scene_file(), out), path("stderr.txt"));
    ASSERT_TRUE(eventually([&] { return fs::exists(out); }, 60)) << read_text(path("stderr.txt"));
    child.send_signal(SIGHUP);
    const ProcessResult result = child.wait(60);
    EXPECT_EQ(result.exit_code, 129) << result.err;
    EXPECT_THAT(result.err, HasSubstr("interrupted: wrote"));
    EXPECT_GE(orb::exr::read_film_exr(out).film.samples_per_pixel, 1u);
}

TEST_F(OutputSafety, TemporariesOfDeadProcessesAreRemovedByTheNextWrite) {
    const std::string dead = std::to_string(a_dead_pid()), alive = std::to_string(::getpid());
    const std::vector<std::string> stale{".out.json.tmp-" + dead + "-0badc0de"};
    const std::vector<std::string> kept{".out.json.tmp-" + alive + "-0badc0de",  // a live process's
                                        ".other.json.tmp-" + dead + "-0badc0de",  // another output's
                                        ".out.json.tmp-notapid"};
    for (const auto& name : stale) write_bytes(path(name), "partial");
    for (const auto& name : kept) write_bytes(path(name), "partial");

    // A failed write tidies nothing (the folder is only inspected on success).
    EXPECT_NE(run("orb-import", {path("missing.json"), "-o", path("out.json")}).exit_code, 0);
    EXPECT_TRUE(fs::exists(path(stale[0])));

    const ProcessResult r = run("orb-import", {scene_file(), "-o", path("out.json")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(fs::exists(path(stale[0])));
    for (const auto& name : kept) EXPECT_TRUE(fs::exists(path(name))) << name;
}
