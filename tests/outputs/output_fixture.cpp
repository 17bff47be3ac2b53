#include "output_fixture.h"

#include <fcntl.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

namespace fs = std::filesystem;

namespace orb::test {

std::string tool(const std::string& name) { return std::string(ORB_BIN_DIR) + "/" + name; }

void OutputSafety::SetUp() {
    // Device nodes and mounts need root; CI runs as root, and a skipped
    // safety test would hide exactly the failures these exist to catch.
    ASSERT_EQ(::geteuid(), 0u) << "the output-safety tests make device nodes and tmpfs mounts: run them as root";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = (fs::temp_directory_path() / ("orb-output-safety-" + std::to_string(::getpid())) /
            (std::string(info->test_suite_name()) + "." + info->name()))
               .string();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
}

void OutputSafety::TearDown() {
    for (const std::string& mount : mounts_) ::umount2(mount.c_str(), MNT_DETACH);
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
}

std::string OutputSafety::path(const std::string& name) const { return (fs::path(dir_) / name).string(); }

std::vector<std::string> OutputSafety::tiny_render_args(const std::string& scene) const {
    return {scene, "--width", "16", "--height", "12", "--spp", "1", "-q"};
}

std::string OutputSafety::scene_file(const std::string& name) const {
    const std::string file = path(name);
    write_bytes(file, read_bytes(std::string(ORB_SCENES_DIR) + "/cornell.json"));
    return file;
}

std::string OutputSafety::tiny_exr(const std::string& name) const {
    const std::string file = path(name);
    std::vector<std::string> args = tiny_render_args(scene_file("tiny-scene.json"));
    // Every layer, so that the tools that handle several (orb-diff --all-passes) have them.
    args.insert(args.end(), {"-o", file, "--passes", "all"});
    const ProcessResult r = run("orb-render", args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    fs::remove(path("tiny-scene.json"));
    return file;
}

ProcessResult OutputSafety::run(const std::string& tool_name, const std::vector<std::string>& args) const {
    std::vector<std::string> argv{tool(tool_name)};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_process(argv);
}

std::string OutputSafety::make_char_device(const std::string& name, unsigned major, unsigned minor) const {
    const std::string file = path(name);
    EXPECT_EQ(::mknod(file.c_str(), S_IFCHR | 0666, makedev(major, minor)), 0) << file;
    return file;
}

std::string OutputSafety::make_fifo(const std::string& name) const {
    const std::string file = path(name);
    EXPECT_EQ(::mkfifo(file.c_str(), 0666), 0) << file;
    return file;
}

std::string OutputSafety::mount_tmpfs(const std::string& name, std::size_t bytes) {
    const std::string folder = path(name);
    fs::create_directories(folder);
    const std::string options = "size=" + std::to_string(bytes);
    EXPECT_EQ(::mount("tmpfs", folder.c_str(), "tmpfs", 0, options.c_str()), 0) << "mount tmpfs on " << folder;
    mounts_.push_back(folder);
    return folder;
}

std::vector<std::string> OutputSafety::files(const std::string& folder) const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder.empty() ? dir_ : folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

bool is_char_device(const std::string& path, unsigned major, unsigned minor) {
    struct stat st {};
    return ::lstat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode) && st.st_rdev == makedev(major, minor);
}

FifoReader::FifoReader(std::string path) : path_(std::move(path)) {
    thread_ = std::thread([this] {
        const int fd = ::open(path_.c_str(), O_RDONLY);
        if (fd < 0) {
            done_ = true;
            return;
        }
        char buffer[1 << 16];
        ssize_t n;
        while ((n = ::read(fd, buffer, sizeof buffer)) > 0) received_.append(buffer, static_cast<size_t>(n));
        ::close(fd);
        done_ = true;
    });
}

std::string FifoReader::finish() {
    if (thread_.joinable()) {
        // If the tool never opened the FIFO, the reader still waits in open():
        // a writer of our own releases it (and then closes at once).
        while (!done_) {
            const int fd = ::open(path_.c_str(), O_WRONLY | O_NONBLOCK);
            if (fd >= 0) ::close(fd);
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        thread_.join();
    }
    return received_;
}

FifoReader::~FifoReader() { finish(); }

}  // namespace orb::test
