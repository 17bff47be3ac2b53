// Shared set-up for the output-safety tests: a scratch folder per test, the
// tools, a tiny scene and EXR to feed them, and the special files the
// tests write into (device nodes, FIFOs, tmpfs mounts), all made inside the
// scratch folder and removed with it.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/types.h>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "process.h"

namespace orb::test {

std::string tool(const std::string& name);  // path of orb-render, orb-import, ...

class OutputSafety : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;  // unmounts what mount_tmpfs mounted, removes the folder

    std::string path(const std::string& name) const;
    // A tiny render's arguments: the Cornell box at 16x12, 1 spp.
    std::vector<std::string> tiny_render_args(const std::string& scene) const;
    std::string scene_file(const std::string& name = "scene.json") const;  // a copy of cornell.json
    std::string tiny_exr(const std::string& name = "in.exr") const;        // rendered once per test

    ProcessResult run(const std::string& tool_name, const std::vector<std::string>& args) const;

    // Device nodes made with mknod (root only), e.g. (1,3) behaves as /dev/null, (1,7) as /dev/full.
    std::string make_char_device(const std::string& name, unsigned major, unsigned minor) const;
    std::string make_fifo(const std::string& name) const;
    // A tmpfs of `bytes` mounted on a new folder `name`; unmounted in TearDown.
    std::string mount_tmpfs(const std::string& name, std::size_t bytes);

    // Names in `folder` (default the scratch folder), sorted, hidden ones included.
    std::vector<std::string> files(const std::string& folder = "") const;

    std::string dir_;
    std::vector<std::string> mounts_;
};

std::string read_bytes(const std::string& path);
void write_bytes(const std::string& path, const std::string& bytes);
bool is_char_device(const std::string& path, unsigned major, unsigned minor);

// Reads a FIFO on a thread while a tool writes into it.
class FifoReader {
public:
    explicit FifoReader(std::string path);
    ~FifoReader();  // unblocks and joins the thread if the writer never came
    std::string finish();  // waits for the writer to close, returns what came through

private:
    std::string path_;
    std::string received_;
    std::atomic<bool> done_{false};
    std::thread thread_;
};

}  // namespace orb::test
