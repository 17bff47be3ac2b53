// Replays every regression input under tests/fuzz/corpus/<target>/ through the
// same checks the libFuzzer targets make, in ordinary (non-fuzz) builds.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "fuzz_checks.h"
#include "scn_test_util.h"

namespace orb {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> corpus_files(const std::string& target) {
    std::vector<fs::path> files;
    const fs::path dir = fs::path(ORB_FUZZ_CORPUS_DIR) / target;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

void replay(const std::string& target, const std::function<void(std::string_view)>& check) {
    const auto files = corpus_files(target);
    ASSERT_FALSE(files.empty()) << "no regression inputs in corpus/" << target;
    for (const auto& file : files) {
        const std::string bytes = test::read_file(file.string());
        EXPECT_NO_THROW(check(bytes)) << file;
    }
}

TEST(FuzzCorpus, ScnInputsAreAcceptedOrCleanlyRejected) { replay("fuzz_scn", fuzz::check_scn_input); }

TEST(FuzzCorpus, SceneJsonInputsAreAcceptedOrCleanlyRejected) {
    replay("fuzz_scene_json", fuzz::check_scene_json_input);
}

TEST(FuzzCorpus, PlyInputsAreAcceptedOrCleanlyRejected) { replay("fuzz_ply", fuzz::check_ply_input); }

TEST(FuzzCorpus, SceneBinaryInputsAreAcceptedOrCleanlyRejected) {
    replay("fuzz_scene_binary", fuzz::check_scene_binary_input);
}

TEST(FuzzCorpus, MolecularInputsAreAcceptedOrCleanlyRejected) {
    replay("fuzz_molecular", fuzz::check_molecular_input);
}

// The shared scenes are part of the seed corpus too; they must pass the same checks.
TEST(FuzzCorpus, SharedScenesPassTheFuzzChecks) {
    for (const auto& entry : fs::directory_iterator(ORB_SCENES_DIR)) {
        if (entry.path().extension() != ".scn") continue;
        EXPECT_NO_THROW(fuzz::check_scn_input(test::read_file(entry.path().string()))) << entry.path();
    }
}

}  // namespace
}  // namespace orb
