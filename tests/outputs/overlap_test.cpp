// An output must never be an input: every output option of every tool
// against every input, by device and inode (so "./a", a symbolic link and a
// hard link count), refused with a usage error naming both, nothing touched.
// The one exception is the documented in-place orb-render --resume X -o X.
#include <unistd.h>

#include <filesystem>

#include "output_fixture.h"

namespace fs = std::filesystem;
using namespace orb::test;
using ::testing::HasSubstr;

namespace {

struct Case {
    std::string tool;
    std::vector<std::string> args;
    // Both must be named in the message: an option by its name, an argument as "the input".
    std::string output_option, input_name;
};

}  // namespace

TEST_F(OutputSafety, EveryOutputOptionIsComparedWithEveryInput) {
    // A JSON scene named .exr, so that orb-render's EXR-name check lets the
    // overlap itself be what is refused.
    const std::string scene = path("scene.exr");
    write_bytes(scene, read_bytes(scene_file()));
    const std::string exr = tiny_exr("a.exr");
    const std::string other = tiny_exr("b.exr");
    fs::create_hard_link(exr, path("hard.exr"));
    fs::create_symlink("a.exr", path("link.exr"));
    const std::string config = path("config.ocio");
    write_bytes(config, read_bytes(std::string(ORB_BIN_DIR) + "/../share/orb/ocio/config.ocio"));
    fs::create_directories(path("frames"));
    write_bytes(path("frames/f.0001.exr"), read_bytes(exr));

    const std::string dot_exr = "./" + fs::relative(exr, fs::current_path()).string();
    const std::vector<std::string> r = tiny_render_args(scene);
    auto render = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = r;
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    };
    const std::vector<Case> cases{
        {"orb-render", render({"-o", scene}), "-o", "the input"},
        {"orb-render", render({"-o", path("out.exr"), "--stats-json", scene}), "--stats-json", "the input"},
        {"orb-render", {scene, "--resume", exr, "-o", path("out.exr"), "--stats-json", path("hard.exr")}, "--stats-json", "--resume"},
        {"orb-import", {scene, "-o", scene}, "-o", "the input"},
        {"orb-import", {path("link.exr"), "-o", path("hard.exr")}, "-o", "the input"},
        {"orb-tonemap", {exr, "-o", dot_exr}, "-o", "the input"},
        {"orb-tonemap", {exr, "-o", path("link.exr")}, "-o", "the input"},
        {"orb-tonemap", {exr, "-o", config, "--format", "png", "--config", config}, "-o", "--config"},
        {"orb-tonemap", {exr, other, "-o", path("frames")}, "", ""},  // control: no overlap, must pass
        {"orb-tonemap", {path("frames/f.%04d.exr"), "--frames", "1-1", "-o", path("frames/f.%04d.exr")}, "-o", "the input"},
        {"orb-tonemap", {exr, "--contact-sheet", "-o", path("hard.exr")}, "-o", "the input"},
        {"orb-diff", {exr, other, "--json", path("hard.exr")}, "--json", "the input"},
        {"orb-diff", {exr, other, "--diff-image", other}, "--diff-image", "the input"},
        {"orb-diff", {exr, other, "--all-passes", "--diff-image", path("a.exr")}, "", ""},  // writes a.<pass>.exr: allowed
        {"orb-diff", {exr, other, "--json", config, "--config", config}, "--json", "--config"},
    };
    for (const Case& c : cases) {
        const std::string before_a = read_bytes(exr), before_scene = read_bytes(scene), before_config = read_bytes(config);
        std::vector<std::string> args = c.args;
        args.push_back("-q");
        const ProcessResult result = run(c.tool, args);
        const std::string what = c.tool + " " + ::testing::PrintToString(c.args);
        if (c.output_option.empty()) {
            EXPECT_LE(result.exit_code, 1) << what << ": " << result.err;  // orb-diff: 1 = the images differ
            EXPECT_THAT(result.err, ::testing::Not(HasSubstr("same file"))) << what;
            continue;
        }
        EXPECT_EQ(result.exit_code, 2) << what << ": " << result.err;
        EXPECT_THAT(result.err, HasSubstr("the same file")) << what;
        EXPECT_THAT(result.err, HasSubstr(c.output_option + " ")) << what;
        EXPECT_THAT(result.err, HasSubstr(c.input_name + " ")) << what;
        EXPECT_THAT(result.err, ::testing::Not(HasSubstr("input input"))) << what;
        EXPECT_EQ(read_bytes(exr), before_a) << what;
        EXPECT_EQ(read_bytes(scene), before_scene) << what;
        EXPECT_EQ(read_bytes(config), before_config) << what;
    }
    // No temporary or lock file was left anywhere.
    for (const std::string& name : files()) EXPECT_NE(name[0], '.') << name;
    for (const std::string& name : files(path("frames"))) EXPECT_NE(name[0], '.') << name;
}

TEST_F(OutputSafety, TwoOutputsNamingOneFileAreAUsageError) {
    std::vector<std::string> args = tiny_render_args(scene_file());
    args.insert(args.end(), {"-o", path("out.exr"), "--stats-json", "./" + fs::relative(path("out.exr")).string()});
    const ProcessResult r = run("orb-render", args);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_THAT(r.err, HasSubstr("are the same file"));
    EXPECT_FALSE(fs::exists(path("out.exr")));
}

TEST_F(OutputSafety, ResumingInPlaceIsTheOneAllowedOverwrite) {
    const std::string scene = scene_file();
    std::vector<std::string> args = tiny_render_args(scene);
    args.insert(args.end(), {"-o", path("r.exr")});
    ASSERT_EQ(run("orb-render", args).exit_code, 0);
    const ProcessResult r = run("orb-render", {scene, "--resume", path("r.exr"), "-o", path("r.exr"), "--spp", "3", "-q"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(files(), (std::vector<std::string>{"r.exr", "scene.json"}));
}
