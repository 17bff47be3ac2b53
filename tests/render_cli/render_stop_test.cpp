// When orb-render stops: at --spp, at --time, on SIGINT/SIGTERM; and the
// checkpoints it writes on the way.
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "cli_fixture.h"
#include "orb/exr/film_exr.h"

using namespace orb::test;

TEST_F(RenderCli, StopsExactlyAtSpp) {
    const auto run = render({write_scene(small_scene()), "-o", path("out.exr"), "--spp", "13"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(orb::exr::read_film_exr(path("out.exr")).film.samples_per_pixel, 13u);
}

TEST_F(RenderCli, StopsAtTheTimeLimit) {
    const auto run = render({write_scene(small_scene()), "-o", path("out.exr"), "--spp", "100000000", "--time", "1",
                             "--stats-json", path("stats.json")});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto film = orb::exr::read_film_exr(path("out.exr"));
    EXPECT_GE(film.film.samples_per_pixel, 1u);
    EXPECT_LT(film.film.samples_per_pixel, 100000000u);
    EXPECT_GE(film.metadata.render_seconds, 1.0);
    EXPECT_LT(film.metadata.render_seconds, 5.0);  // passes are cut to the time left
    EXPECT_NE(read_text(path("stats.json")).find("\"stop_reason\": \"time\""), std::string::npos);
}

TEST_F(RenderCli, CheckpointFileAppearsWhileRendering) {
    const std::string out = path("out.exr");
    Child child({render_exe(), write_scene(small_scene()), "-o", out, "--spp", "100000000", "--time", "20",
                 "--checkpoint", "0.2"},
                path("stderr.txt"));
    ASSERT_TRUE(eventually([&] { return std::filesystem::exists(out); }, 60)) << read_text(path("stderr.txt"));
    EXPECT_TRUE(child.running()) << "the file should appear before the render ends";
    const auto first = orb::exr::read_film_exr(out);  // a complete, valid image (renamed into place)
    EXPECT_GE(first.film.samples_per_pixel, 1u);
    ASSERT_TRUE(eventually([&] { return orb::exr::read_film_exr(out).film.samples_per_pixel >
                                        first.film.samples_per_pixel; }, 20));
    child.send_signal(SIGINT);
    const auto result = child.wait(60);
    EXPECT_EQ(result.exit_code, 130) << result.err;
    // Not a terminal: one plain line per checkpoint.
    EXPECT_NE(result.err.find("checkpoint " + out), std::string::npos) << result.err;
}

TEST_F(RenderCli, SigintFinishesThePassWritesTheImageAndExits130) {
    const std::string out = path("out.exr");
    Child child({render_exe(), write_scene(small_scene()), "-o", out, "--spp", "100000000", "--checkpoint", "0.1"},
                path("stderr.txt"));
    // Wait for the first checkpoint: rendering is under way.
    ASSERT_TRUE(eventually([&] { return std::filesystem::exists(out); }, 60)) << read_text(path("stderr.txt"));
    child.send_signal(SIGINT);
    const auto result = child.wait(60);
    EXPECT_EQ(result.exit_code, 130) << result.err;
    EXPECT_NE(result.err.find("interrupted"), std::string::npos) << result.err;
    const auto film = orb::exr::read_film_exr(out);
    EXPECT_GE(film.film.samples_per_pixel, 1u);
    EXPECT_LT(film.film.samples_per_pixel, 100000000u);
    EXPECT_EQ(film.metadata.target_spp, 100000000u);  // so --resume carries on toward it
    EXPECT_EQ(files(), (std::vector<std::string>{"out.exr", "scene.json", "stderr.txt"}));  // no temporaries
}

TEST_F(RenderCli, SigtermAlsoWritesTheImageAndExits143) {
    const std::string out = path("out.exr");
    Child child({render_exe(), write_scene(small_scene()), "-o", out, "--spp", "100000000", "--checkpoint", "0.1"},
                path("stderr.txt"));
    ASSERT_TRUE(eventually([&] { return std::filesystem::exists(out); }, 60)) << read_text(path("stderr.txt"));
    const auto before = std::filesystem::last_write_time(out);
    child.send_signal(SIGTERM);
    const auto result = child.wait(60);
    EXPECT_EQ(result.exit_code, 143) << result.err;
    EXPECT_GE(std::filesystem::last_write_time(out), before);
    EXPECT_GE(orb::exr::read_film_exr(out).film.samples_per_pixel, 1u);
}

TEST_F(RenderCli, InterruptedRenderResumesToItsTargetAndMatchesAnUninterruptedOne) {
    const std::string scene = write_scene(small_scene());
    const std::string out = path("out.exr");
    Child child({render_exe(), scene, "-o", out, "--spp", "3000", "--seed", "11", "--checkpoint", "0.05"},
                path("stderr.txt"));
    ASSERT_TRUE(eventually([&] { return std::filesystem::exists(out); }, 60)) << read_text(path("stderr.txt"));
    child.send_signal(SIGINT);
    const auto stopped = child.wait(60);
    ASSERT_EQ(stopped.exit_code, 130) << stopped.err;
    ASSERT_LT(orb::exr::read_film_exr(out).film.samples_per_pixel, 3000u);

    const auto resumed = render({scene, "--resume", out, "-o", out});  // no --spp: the stored target
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    ASSERT_EQ(render({scene, "-o", path("whole.exr"), "--spp", "3000", "--seed", "11"}).exit_code, 0);
    EXPECT_EQ(orb::exr::read_film_exr(out).film.samples_per_pixel, 3000u);
    expect_same_image(path("whole.exr"), out);
}
