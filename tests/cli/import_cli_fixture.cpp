#include "import_cli_fixture.h"

#include <stdlib.h>

#include <algorithm>
#include <fstream>

namespace fs = std::filesystem;

namespace orb::test {

void ImportCliFixture::SetUp() {
    std::string dir = (fs::temp_directory_path() / "orb-import-cli-XXXXXX").string();
    ASSERT_NE(mkdtemp(dir.data()), nullptr);
    dir_ = dir;
}

void ImportCliFixture::TearDown() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
}

ProcessResult ImportCliFixture::run(const std::vector<std::string>& args, const std::string& stdin_bytes) const {
    return run_process(ORB_IMPORT_EXE, args, stdin_bytes, dir_.string());
}

fs::path ImportCliFixture::write(const std::string& name, const std::string& bytes) const {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return dir_ / name;
}

std::vector<std::string> ImportCliFixture::files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace orb::test
