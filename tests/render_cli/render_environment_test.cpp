// orb-render where PoCL cannot use $HOME (docker --user, a read-only or
// missing home): it still finds its platform, and keeps its caches inside
// what it was given. Every path involved is inside the test's own folder.
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "cli_fixture.h"

using namespace orb::test;
namespace fs = std::filesystem;

namespace {

// orb-render (`exe`) under `env`: XDG_CACHE_HOME and POCL_CACHE_DIR unset,
// HOME and TMPDIR as given, optionally as another user first (`prefix`).
std::vector<std::string> in_environment(const std::vector<std::string>& prefix, const std::string& home,
                                        const std::string& tmpdir, const std::vector<std::string>& args,
                                        const std::string& exe = render_exe()) {
    std::vector<std::string> argv = prefix;
    for (const std::string& word : {std::string("/usr/bin/env"), std::string("-u"), std::string("XDG_CACHE_HOME"),
                                    std::string("-u"), std::string("POCL_CACHE_DIR"), "HOME=" + home, "TMPDIR=" + tmpdir,
                                    exe})
        argv.push_back(word);
    argv.insert(argv.end(), args.begin(), args.end());
    return argv;
}

orb::Scene tiny_scene() {
    orb::Scene scene = small_scene();
    scene.render.width = 8;
    scene.render.height = 6;
    scene.render.spp = 1;
    return scene;
}

}  // namespace

TEST_F(RenderCli, HomeThatIsAFileStillFindsPocl) {
    // Nothing can be created under a regular file, not even by root.
    std::ofstream(path("home")) << "not a directory";
    const std::string scene = write_scene(tiny_scene());
    const auto run = run_process(in_environment({}, path("home"), dir_, {scene, "-o", path("out.exr")}));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err.find("no OpenCL platform"), std::string::npos) << run.err;
    EXPECT_TRUE(fs::exists(path("out.exr")));
    // PoCL's private cache went under TMPDIR and is gone again.
    EXPECT_EQ(files(), (std::vector<std::string>{"home", "out.exr", "scene.json"}));
}

TEST_F(RenderCli, PoclCacheGoesIntoOrbsCacheWhenHomeIsWritable) {
    fs::create_directory(path("home"));
    const std::string scene = write_scene(tiny_scene());
    const auto run = run_process(in_environment({}, path("home"), dir_, {scene, "-o", path("out.exr")}));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(fs::is_directory(path("home/.cache/orb/pocl")));
    EXPECT_FALSE(fs::exists(path("home/.cache/pocl")));
    EXPECT_EQ(files(), (std::vector<std::string>{"home", "out.exr", "scene.json"}));
}

TEST_F(RenderCli, UnprivilegedUserWithAnUnusableHomeStillRenders) {
    ASSERT_EQ(::geteuid(), 0u) << "this test drops to uid 65534 with setpriv and needs root (CI runs as root)";
    std::ofstream(path("home")) << "not a directory";
    const std::string scene = write_scene(tiny_scene());
    ASSERT_EQ(::chmod(dir_.c_str(), 0777), 0);  // nobody writes the image and the private cache here
    // nobody runs a copy in this folder: the build tree may lie under a
    // folder closed to others (a clone in /root, as on a fresh machine).
    fs::create_directory(path("bin"));
    const std::string exe = path("bin/orb-render");
    fs::copy_file(render_exe(), exe);
    fs::permissions(exe, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                             fs::perms::others_read | fs::perms::others_exec);
    const auto run = run_process(in_environment({"/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"},
                                                path("home"), dir_, {scene, "-o", path("out.exr")}, exe));
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err.find("no OpenCL platform"), std::string::npos) << run.err;
    struct stat image {};
    ASSERT_EQ(::stat(path("out.exr").c_str(), &image), 0);
    EXPECT_EQ(image.st_uid, 65534u);
    EXPECT_EQ(files(), (std::vector<std::string>{"bin", "home", "out.exr", "scene.json"}));
}
