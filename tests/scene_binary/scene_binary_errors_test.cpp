// A broken binary scene is refused with one message naming the file, in the
// same words as the JSON form where the rule is the scene's own.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "binary_test_scene.h"
#include "orb/scene/error.h"
#include "orb/scene/scene_binary.h"

namespace orb {
namespace {

using ::testing::StartsWith;

std::string error_of(const std::string& bytes) {
    try {
        load_scene_binary(bytes, "big.orb");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

Scene unnamed_scene() {
    Scene scene = test::every_feature_scene();
    for (Sphere& s : scene.spheres) s.name.clear();
    return scene;
}

// Where the sphere arrays start: after the preamble, the header and padding.
std::size_t arrays_offset(const std::string& bytes) {
    std::uint32_t header = 0;
    std::memcpy(&header, bytes.data() + 12, 4);
    const std::size_t end = 16 + header;
    return end + (8 - end % 8) % 8;
}

template <typename T>
void poke(std::string& bytes, std::size_t offset, T value) {
    std::memcpy(bytes.data() + offset, &value, sizeof value);
}

TEST(SceneBinaryErrors, WrongMagic) {
    std::string bytes = write_scene_binary(unnamed_scene());
    bytes[1] = 'X';
    EXPECT_EQ(error_of(bytes), "big.orb: not an Orb binary scene (the file does not start with its magic bytes)");
}

TEST(SceneBinaryErrors, NewerVersion) {
    std::string bytes = write_scene_binary(unnamed_scene());
    poke<std::uint32_t>(bytes, 8, 3);
    EXPECT_EQ(error_of(bytes), "big.orb: this is a version 3 binary scene; this Orb reads up to version 2");
}

TEST(SceneBinaryErrors, TruncatedAnywhere) {
    const std::string whole = write_scene_binary(unnamed_scene());
    EXPECT_EQ(error_of(whole.substr(0, 10)), "big.orb: truncated: the file ends inside the binary preamble");
    EXPECT_THAT(error_of(whole.substr(0, 40)), StartsWith("big.orb: truncated: the header says it is "));
    EXPECT_EQ(error_of(whole.substr(0, whole.size() - 1)),
              "big.orb: truncated: the header says 50 spheres (36 bytes each), but only 1799 bytes follow it");
    const std::string named = write_scene_binary(test::every_feature_scene());
    EXPECT_EQ(error_of(named.substr(0, named.size() - 3)),
              "big.orb: truncated: spheres[49].name runs past the end of the file");
}

TEST(SceneBinaryErrors, TrailingBytes) {
    EXPECT_EQ(error_of(write_scene_binary(unnamed_scene()) + "xyz"),
              "big.orb: 3 bytes after the end of the sphere arrays (the file is corrupt)");
}

TEST(SceneBinaryErrors, NanCentreAndBadRadiusUseTheSceneRules) {
    std::string bytes = write_scene_binary(unnamed_scene());
    const std::size_t arrays = arrays_offset(bytes);
    std::string nan = bytes;
    poke(nan, arrays + 24 * 7 + 8, std::numeric_limits<double>::quiet_NaN());
    EXPECT_EQ(error_of(nan), "big.orb: spheres[7].center: expected finite numbers");
    std::string negative = bytes;
    poke(negative, arrays + 24 * 50 + 8 * 4, -2.0);
    EXPECT_EQ(error_of(negative), "big.orb: spheres[4].radius: must be > 0, got -2");
}

TEST(SceneBinaryErrors, MaterialIndexOutOfRange) {
    std::string bytes = write_scene_binary(unnamed_scene());
    poke<std::uint32_t>(bytes, arrays_offset(bytes) + 36 * 50 - 4, 6);
    EXPECT_EQ(error_of(bytes), "big.orb: spheres[49].material: index 6 is out of range (there are 6 materials)");
}

TEST(SceneBinaryErrors, HeaderProblems) {
    std::string bytes = write_scene_binary(unnamed_scene());
    std::string not_json = bytes;
    not_json[16] = '[';
    EXPECT_EQ(error_of(not_json), "big.orb: header: expected a JSON object (the file is corrupt)");
    // A camera problem reads as in the JSON form.
    std::string camera = bytes;
    const std::size_t vfov = camera.find("\"vfov_deg\":33.3");
    ASSERT_NE(vfov, std::string::npos);
    camera.replace(vfov, 15, "\"vfov_deg\":-3.3");
    EXPECT_EQ(error_of(camera), "big.orb: camera.vfov_deg: must be in (0, 180), got -3.3");
    // So does a negative orthographic height (same length of text: the header size stays right).
    Scene orthographic = unnamed_scene();
    orthographic.camera.orthographic_height = 2.5;
    std::string height = write_scene_binary(orthographic);
    const std::size_t at = height.find("\"orthographic_height\":2.5");
    ASSERT_NE(at, std::string::npos);
    height.replace(at + 22, 3, "-25");
    EXPECT_THAT(error_of(height), StartsWith("big.orb: camera.orthographic_height: must be 0 (a perspective camera) or "
                                             "in [1e-18, 1e+18]"));
}

TEST(SceneBinaryErrors, NamesMustBeUtf8) {
    std::string bytes = write_scene_binary(test::every_feature_scene());
    const std::size_t name = bytes.rfind("sphère 49");
    ASSERT_NE(name, std::string::npos);
    bytes[name + 3] = '\xff';
    EXPECT_EQ(error_of(bytes), "big.orb: spheres[49].name: not valid UTF-8");
}

}  // namespace
}  // namespace orb
