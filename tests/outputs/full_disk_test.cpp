// A full disk during any write is an error naming the file, with a non-zero
// exit; the temporary is removed and a previous good file is untouched. The
// disk is a tmpfs mounted in the test's own folder and filled to its last
// page, which the output's lock file takes, so the write itself fails.
#include <fcntl.h>
#include <unistd.h>

#include <filesystem>

#include "output_fixture.h"

namespace fs = std::filesystem;
using namespace orb::test;
using ::testing::HasSubstr;

namespace {

// Fills `folder` with a filler file, then gives back exactly one page.
void fill_leaving_one_page(const std::string& folder) {
    const std::string filler = folder + "/filler";
    const int fd = ::open(filler.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ASSERT_GE(fd, 0);
    const std::string page(4096, 'x');
    off_t size = 0;
    while (::write(fd, page.data(), page.size()) == static_cast<ssize_t>(page.size())) size += 4096;
    ASSERT_GE(size, 4096);
    ASSERT_EQ(::ftruncate(fd, size - 4096), 0);
    ::close(fd);
}

struct Case {
    std::string tool;
    std::vector<std::string> args;  // "OUT" stands for the output on the full disk
    int exit_code;
};

}  // namespace

TEST_F(OutputSafety, AFullDiskFailsEveryWriterAndKeepsThePreviousFile) {
    const std::string scene = scene_file();
    const std::string a = tiny_exr("a.exr"), b = tiny_exr("b.exr");
    std::vector<std::string> render = tiny_render_args(scene);
    const std::vector<Case> cases{
        {"orb-render", [&] { auto r = render; r.insert(r.end(), {"-o", "OUT.exr"}); return r; }(), 1},
        {"orb-render", [&] { auto r = render; r.insert(r.end(), {"-o", path("fine.exr"), "--stats-json", "OUT.json"}); return r; }(), 1},
        {"orb-import", {scene, "-o", "OUT.json"}, 1},
        {"orb-import", {scene, "--to", "scn", "-o", "OUT.scn"}, 1},
        {"orb-tonemap", {a, "-o", "OUT.png", "-q"}, 1},
        {"orb-tonemap", {a, "-o", "OUT.jpg", "-q"}, 1},
        {"orb-tonemap", {a, "-o", "OUT.exr", "-q"}, 1},
        {"orb-diff", {a, b, "--diff-image", "OUT.png", "-q"}, 2},  // orb-diff's errors are 2 (1 = the images differ)
        {"orb-diff", {a, b, "--json", "OUT.json", "-q"}, 2},
    };
    int index = 0;
    for (const Case& c : cases) {
        const std::string disk = mount_tmpfs("disk" + std::to_string(index++), 64 * 1024);
        std::vector<std::string> args = c.args;
        std::string out;
        for (std::string& arg : args)
            if (arg.rfind("OUT.", 0) == 0) arg = out = disk + "/out" + arg.substr(3);
        write_bytes(out, "previous good content");
        fill_leaving_one_page(disk);

        const ProcessResult r = run(c.tool, args);
        const std::string what = c.tool + " " + ::testing::PrintToString(c.args);
        EXPECT_EQ(r.exit_code, c.exit_code) << what << ": " << r.err;
        EXPECT_THAT(r.err, HasSubstr(out + ": cannot write (")) << what;  // the write itself, not the lock
        EXPECT_THAT(r.err, HasSubstr("No space left on device")) << what;
        EXPECT_THAT(r.err, ::testing::Not(HasSubstr("wrote"))) << what;
        EXPECT_EQ(read_bytes(out), "previous good content") << what;
        EXPECT_EQ(files(disk), (std::vector<std::string>{"filler", fs::path(out).filename().string()})) << what;
    }
}

// A checkpoint that hits a full disk is a warning; the render goes on, and
// its final write reports the error for good.
TEST_F(OutputSafety, AFullDiskAtACheckpointIsAWarningThenTheFinalWriteFails) {
    const std::string disk = mount_tmpfs("disk", 64 * 1024);
    fill_leaving_one_page(disk);
    std::vector<std::string> args = tiny_render_args(scene_file());
    args[6] = "1000000";
    args.insert(args.end(), {"-o", disk + "/out.exr", "--checkpoint", "0.3", "--time", "1.5"});
    args.erase(std::find(args.begin(), args.end(), "-q"));
    const ProcessResult r = run("orb-render", args);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_THAT(r.err, HasSubstr("warning: checkpoint not written: " + disk + "/out.exr: cannot write"));
    EXPECT_THAT(r.err, HasSubstr("error: " + disk + "/out.exr: cannot write (-o): No space left on device"));
    EXPECT_EQ(files(disk), (std::vector<std::string>{"filler"}));
}
