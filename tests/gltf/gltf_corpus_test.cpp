// Every file of the Khronos glTF-Validator corpus (tests/data/gltf-validator-corpus,
// mostly malformed on purpose) imports or fails with an InputError: never a
// crash, a hang or another exception. The sanitizer build runs this under ASan/UBSan.
#include <gtest/gtest.h>

#include <filesystem>

#include "gltf_test_util.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_json.h"

namespace orb::gltf_test {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> corpus_files() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(ORB_GLTF_CORPUS_DIR)) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb")) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(GltfCorpus, EveryValidatorFileImportsOrFailsCleanly) {
    ASSERT_TRUE(fs::is_directory(ORB_GLTF_CORPUS_DIR)) << "missing corpus " << ORB_GLTF_CORPUS_DIR;
    const std::vector<fs::path> files = corpus_files();
    // 335 .gltf + 37 .glb in the copy of the corpus this project carries.
    ASSERT_EQ(files.size(), 372u);
    std::size_t imported = 0, refused = 0;
    for (const fs::path& file : files) {
        const std::string source = file.string();
        try {
            const GltfImportResult result = import_gltf(read_file(source), source, file.parent_path().string(), {});
            // What was imported must survive the canonical JSON round trip.
            EXPECT_EQ(load_scene_json(write_scene_json(result.scene), source), result.scene) << source;
            ++imported;
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind(source + ": ", 0), 0u) << "message should start with the file name: " << message;
            EXPECT_GT(message.size(), source.size() + 10) << message;
            ++refused;
        } catch (const std::exception& e) {
            ADD_FAILURE() << source << ": unexpected exception: " << e.what();
        }
    }
    EXPECT_EQ(imported + refused, files.size());
    // Both outcomes occur: valid samples import, broken ones are refused.
    EXPECT_GT(imported, 50u);
    EXPECT_GT(refused, 50u);
    std::printf("glTF-Validator corpus: %zu imported, %zu refused with a message\n", imported, refused);
}

}  // namespace
}  // namespace orb::gltf_test
