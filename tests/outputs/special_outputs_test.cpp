// What an output path is decides how it is written: devices and FIFOs are
// written into and left alone, symbolic links keep pointing at a target that
// is replaced atomically, and folders that cannot hold the output are
// refused before any work starts.
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "output_fixture.h"

namespace fs = std::filesystem;
using namespace orb::test;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

constexpr unsigned kMem = 1, kNull = 3, kFull = 7;  // Linux's memory devices: /dev/null is 1,3; /dev/full is 1,7

bool looks_like_exr(const std::string& bytes) { return bytes.size() > 4 && bytes.compare(0, 4, "\x76\x2f\x31\x01") == 0; }
bool looks_like_png(const std::string& bytes) { return bytes.size() > 8 && bytes.compare(1, 3, "PNG") == 0; }

}  // namespace

// The incident behind this suite: as root, -o /dev/null replaced the device node.
TEST_F(OutputSafety, EveryToolWritesIntoANullDeviceAndLeavesTheNodeAlone) {
    const std::string null = make_char_device("null", kMem, kNull);
    const std::string scene = scene_file();
    const std::string exr = tiny_exr();

    std::vector<std::string> render = tiny_render_args(scene);
    render.insert(render.end(), {"-o", null, "--stats-json", null});
    const std::vector<std::pair<std::string, std::vector<std::string>>> runs{
        {"orb-render", render},
        {"orb-import", {scene, "-o", null}},
        {"orb-tonemap", {exr, "-o", null, "--format", "png", "-q"}},
        {"orb-diff", {exr, exr, "--json", null, "--diff-image", null, "-q"}},
        {"orb-merge", {exr, "-o", null, "-q"}},
    };
    for (const auto& [name, args] : runs) {
        const ProcessResult r = run(name, args);
        EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
        EXPECT_TRUE(is_char_device(null, kMem, kNull)) << name << " replaced the device node";
    }
    EXPECT_EQ(files(), (std::vector<std::string>{"in.exr", "null", "scene.json"}));
}

TEST_F(OutputSafety, AFullDeviceIsAWriteErrorNamingTheFile) {
    const std::string full = make_char_device("full", kMem, kFull);
    const std::string scene = scene_file();
    std::vector<std::string> render = tiny_render_args(scene);
    render.insert(render.end(), {"-o", full});

    for (const auto& [name, args, code] : std::vector<std::tuple<std::string, std::vector<std::string>, int>>{
             {"orb-render", render, 1},
             {"orb-import", {scene, "-o", full}, 1},
             {"orb-diff", {tiny_exr(), path("in.exr"), "--json", full, "-q"}, 2},
             {"orb-merge", {path("in.exr"), "-o", full, "-q"}, 1}}) {
        const ProcessResult r = run(name, args);
        EXPECT_EQ(r.exit_code, code) << name << ": " << r.err;
        EXPECT_THAT(r.err, HasSubstr(full + ": cannot write")) << name;
        EXPECT_THAT(r.err, HasSubstr("No space left on device")) << name;
        EXPECT_TRUE(is_char_device(full, kMem, kFull)) << name;
    }
}

TEST_F(OutputSafety, AFifoBehavesLikeAPipe) {
    const std::string fifo = make_fifo("fifo");
    const std::string scene = scene_file();
    {
        FifoReader reader(fifo);
        std::vector<std::string> args = tiny_render_args(scene);
        args.insert(args.end(), {"-o", fifo});
        const ProcessResult r = run("orb-render", args);
        EXPECT_EQ(r.exit_code, 0) << r.err;
        EXPECT_TRUE(looks_like_exr(reader.finish()));
    }
    {
        FifoReader reader(fifo);
        const ProcessResult r = run("orb-tonemap", {tiny_exr(), "-o", fifo, "--format", "png", "-q"});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        EXPECT_TRUE(looks_like_png(reader.finish()));
    }
    {
        FifoReader reader(fifo);
        const ProcessResult r = run("orb-import", {scene, "-o", fifo});
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const nlohmann::json scene_json = nlohmann::json::parse(reader.finish(), nullptr, false);
        EXPECT_FALSE(scene_json.is_discarded());
        EXPECT_TRUE(scene_json.contains("spheres"));
    }
    struct stat st {};
    ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

TEST_F(OutputSafety, ACheckpointIntoADeviceOrFifoIsAUsageError) {
    const std::string null = make_char_device("null", kMem, kNull);
    std::vector<std::string> args = tiny_render_args(scene_file());
    args.insert(args.end(), {"-o", null, "--checkpoint", "1"});
    const ProcessResult r = run("orb-render", args);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_THAT(r.err, HasSubstr("is a character device"));
    EXPECT_THAT(r.err, Not(HasSubstr("device: ")));  // refused before the OpenCL device was opened
}

TEST_F(OutputSafety, ASymbolicLinkStaysALinkAndItsTargetIsReplaced) {
    fs::create_directories(path("real"));
    const std::string target = path("real/out.exr");
    write_bytes(target, "old");
    fs::create_symlink("real/out.exr", path("link.exr"));
    fs::create_symlink("real/new.json", path("dangling.json"));  // a link to a file not yet made

    std::vector<std::string> args = tiny_render_args(scene_file());
    args.insert(args.end(), {"-o", path("link.exr")});
    ProcessResult r = run("orb-render", args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(path("link.exr")));
    EXPECT_TRUE(looks_like_exr(read_bytes(target)));

    r = run("orb-import", {path("scene.json"), "-o", path("dangling.json")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::is_symlink(path("dangling.json")));
    EXPECT_TRUE(fs::is_regular_file(path("real/new.json")));

    // The temporary went beside the target, and nothing is left of it or the lock.
    EXPECT_EQ(files(path("real")), (std::vector<std::string>{"new.json", "out.exr"}));
    EXPECT_EQ(files(), (std::vector<std::string>{"dangling.json", "link.exr", "real", "scene.json"}));
}

TEST_F(OutputSafety, AReplacedFileKeepsItsPermissions) {
    const std::string out = path("out.json");
    write_bytes(out, "{}");
    ::chmod(out.c_str(), 0640);
    const ProcessResult r = run("orb-import", {scene_file(), "-o", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    struct stat st {};
    ASSERT_EQ(::stat(out.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 07777, 0640u);
}

TEST_F(OutputSafety, AFolderOrAMissingFolderIsRefusedBeforeAnyWork) {
    const std::string scene = scene_file();
    fs::create_directories(path("folder"));
    for (const auto& [output, message] : std::vector<std::pair<std::string, std::string>>{
             {path("folder"), "is a directory"}, {path("missing/out.exr"), "folder " + path("missing") + " does not exist"}}) {
        std::vector<std::string> args = tiny_render_args(scene);
        args[6] = "100000";  // an hour's worth of samples that must not start
        args.insert(args.end(), {"-o", output});
        const ProcessResult r = run("orb-render", args);
        EXPECT_EQ(r.exit_code, 1) << r.err;
        EXPECT_THAT(r.err, HasSubstr(message));
        EXPECT_THAT(r.err, Not(HasSubstr("device: ")));  // no OpenCL device was even opened

        const ProcessResult t = run("orb-tonemap", {tiny_exr(), "-o", output + (output.ends_with(".exr") ? "" : "/"), "-q"});
        EXPECT_NE(t.exit_code, 0);
    }
}

TEST_F(OutputSafety, AReadOnlyFolderIsRefusedBeforeAnyWork) {
    const std::string scene = scene_file();
    const std::string folder = mount_tmpfs("readonly", 1 << 16);
    ASSERT_EQ(::mount(nullptr, folder.c_str(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr), 0);
    std::vector<std::string> args = tiny_render_args(scene);
    args.insert(args.end(), {"-o", folder + "/out.exr"});
    const ProcessResult r = run("orb-render", args);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_THAT(r.err, HasSubstr(folder + "/out.exr: cannot write (-o)"));
    EXPECT_THAT(r.err, HasSubstr("Read-only file system"));
    EXPECT_THAT(r.err, Not(HasSubstr("device: ")));
}

TEST_F(OutputSafety, ANonExrNameForARenderIsAUsageErrorNamingOrbTonemap) {
    for (const std::string name : {"out.png", "out.JPG", "out.tif"}) {
        std::vector<std::string> args = tiny_render_args(scene_file());
        args.insert(args.end(), {"-o", path(name)});
        const ProcessResult r = run("orb-render", args);
        EXPECT_EQ(r.exit_code, 2) << name;
        EXPECT_THAT(r.err, HasSubstr("orb-tonemap")) << name;
        EXPECT_FALSE(fs::exists(path(name)));
    }
    std::vector<std::string> args = tiny_render_args(scene_file());
    args.insert(args.end(), {"-o", path("OUT.EXR")});
    EXPECT_EQ(run("orb-render", args).exit_code, 0);
}
