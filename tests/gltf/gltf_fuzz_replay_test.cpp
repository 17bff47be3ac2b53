// Replays the glTF fuzzer's regression inputs (tests/fuzz/corpus/fuzz_gltf/)
// and the validator corpus through the fuzzer's own check, in every build.
#include <gtest/gtest.h>

#include <filesystem>

#include "gltf_fuzz_check.h"
#include "gltf_test_util.h"

namespace orb::gltf_test {
namespace {

namespace fs = std::filesystem;

void replay_dir(const fs::path& dir, std::size_t minimum) {
    ASSERT_TRUE(fs::is_directory(dir)) << "missing " << dir;
    std::size_t count = 0;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        if (!entry.is_regular_file() || entry.path().filename() == "LICENSE") continue;
        ++count;
        EXPECT_NO_THROW(fuzz::check_gltf_input(read_file(entry.path().string()))) << entry.path();
    }
    EXPECT_GE(count, minimum) << dir;
}

TEST(GltfFuzzCorpus, RegressionInputsPassTheFuzzCheck) { replay_dir(ORB_GLTF_FUZZ_CORPUS_DIR, 9); }

TEST(GltfFuzzCorpus, ValidatorFilesPassTheFuzzCheck) { replay_dir(ORB_GLTF_CORPUS_DIR, 372); }

}  // namespace
}  // namespace orb::gltf_test
