// One case per class of malformed .scn input: each is an InputError whose
// message names file:line:column and what was expected.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "scn_test_util.h"

namespace orb {
namespace {

using test::scn_error;
using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr const char* kCamera = "camera 0 0 10  0 0 0\n";

std::string one_sphere(const std::string& sphere_line) { return std::string(kCamera) + "size 1\n" + sphere_line; }

TEST(ScnErrors, MissingCamera) {
    EXPECT_THAT(scn_error("size 1\nsphere 1 0 0 0 0 0 0 1 1 1 0\n"),
                StartsWith("t.scn:1:1: missing camera: expected 'camera ox oy oz  tx ty tz' before 'size'"));
    EXPECT_THAT(scn_error("\n\nsphere 1 0 0 0 0 0 0 1 1 1 0\n"), StartsWith("t.scn:3:1: missing camera"));
    EXPECT_THAT(scn_error("cam 0 0 1 0 0 0\n"), StartsWith("t.scn:1:1: expected 'camera ox oy oz  tx ty tz', got 'cam'"));
}

TEST(ScnErrors, EmptyFile) {
    EXPECT_THAT(scn_error(""), StartsWith("t.scn:1:1: expected 'camera ox oy oz  tx ty tz', got an empty file"));
    EXPECT_THAT(scn_error("\n \n\t\n"), StartsWith("t.scn:4:1: expected 'camera"));
}

TEST(ScnErrors, MissingSize) {
    EXPECT_THAT(scn_error(kCamera), StartsWith("t.scn:2:1: expected 'size N' after the camera, got end of file"));
    EXPECT_THAT(scn_error(std::string(kCamera) + "sphere 1 0 0 0 0 0 0 1 1 1 0\n"),
                StartsWith("t.scn:2:1: expected 'size N', got 'sphere'"));
}

TEST(ScnErrors, SizeWithFewerSphereLines) {
    EXPECT_THAT(scn_error(std::string(kCamera) + "size 3\nsphere 1 0 0 0 0 0 0 1 1 1 0\n"),
                StartsWith("t.scn:2:6: expected 3 sphere lines after 'size 3', found 1 before the end of file"));
}

TEST(ScnErrors, SizeWithMoreSphereLines) {
    EXPECT_THAT(scn_error(std::string(kCamera) + "size 1\nsphere 1 0 0 0 0 0 0 1 1 1 0\nsphere 1 0 0 0 0 0 0 1 1 1 0\n"),
                StartsWith("t.scn:4:1: expected end of file: 'size 1' on line 2 declares 1 spheres, this is one more"));
}

TEST(ScnErrors, SizeNotAWholeNumber) {
    for (const char* bad : {"-1", "2.5", "1e3", "three", "0x10", ""}) {
        EXPECT_THAT(scn_error(std::string(kCamera) + "size " + bad + "\n"), HasSubstr("expected the sphere count"))
            << bad;
    }
    EXPECT_THAT(scn_error(std::string(kCamera) + "size -1\n"),
                StartsWith("t.scn:2:6: expected the sphere count (a whole number >= 0), got '-1'"));
}

TEST(ScnErrors, AbsurdSizeIsCheapAndClean) {
    // Must not try to allocate four billion spheres before seeing their lines.
    EXPECT_THAT(scn_error(std::string(kCamera) + "size 4000000000\nsphere 1 0 0 0 0 0 0 1 1 1 0\n"),
                StartsWith("t.scn:2:6: expected 4000000000 sphere lines after 'size 4000000000', found 1"));
    EXPECT_THAT(scn_error(std::string(kCamera) + "size 99999999999999999999999\n"),
                StartsWith("t.scn:2:6: expected the sphere count of at most 4294967295, got '99999999999999999999999'"));
    EXPECT_THAT(scn_error(std::string(kCamera) + "size 4294967296\n"), HasSubstr("of at most 4294967295"));
}

TEST(ScnErrors, UnknownMaterialCode) {
    EXPECT_THAT(scn_error(one_sphere("sphere 1  0 0 0  0 0 0  1 1 1  3\n")),
                StartsWith("t.scn:3:32: expected material code 0 (diffuse), 1 (mirror) or 2 (glass), got '3'"));
    for (const char* code : {"-1", "1.0", "01", "glass", "+1"})
        EXPECT_THAT(scn_error(one_sphere(std::string("sphere 1 0 0 0 0 0 0 1 1 1 ") + code)),
                    HasSubstr("expected material code 0 (diffuse), 1 (mirror) or 2 (glass)"))
            << code;
}

TEST(ScnErrors, NonFiniteNumbers) {
    EXPECT_THAT(scn_error("camera inf 0 0  0 0 0\n"),
                StartsWith("t.scn:1:8: expected camera position x (a finite number), got 'inf' (not finite)"));
    EXPECT_THAT(scn_error("camera 0 NaN 0  0 0 0\n"), StartsWith("t.scn:1:10: expected camera position y"));
    EXPECT_THAT(scn_error("camera 0 0 -infinity  0 0 0\n"), HasSubstr("got '-infinity' (not finite)"));
    EXPECT_THAT(scn_error(one_sphere("sphere 1 0 0 0  1e999 0 0  1 1 1  0\n")),
                StartsWith("t.scn:3:17: expected emission r (a finite number), got '1e999' (out of range for a double)"));
}

TEST(ScnErrors, MalformedNumbers) {
    // Hexadecimal is strtod syntax too, but not SmallptGPU's: rejected, as are other non-numbers.
    for (const char* bad : {"0x1p3", "1,5", "1.5.2", "--1", "+-1", "+", "e5", ".", "1e", "1f", "abc"})
        EXPECT_THAT(scn_error(std::string("camera ") + bad + " 0 0  0 0 0\n"),
                    StartsWith(std::string("t.scn:1:8: expected camera position x (a finite number), got '") + bad +
                               "'"))
            << bad;
}

TEST(ScnErrors, RadiusMustBePositive) {
    EXPECT_THAT(scn_error(one_sphere("sphere 0  0 0 0  0 0 0  1 1 1  0\n")),
                StartsWith("t.scn:3:8: expected a radius > 0, got '0'"));
    EXPECT_THAT(scn_error(one_sphere("sphere -2  0 0 0  0 0 0  1 1 1  0\n")),
                StartsWith("t.scn:3:8: expected a radius > 0, got '-2'"));
    EXPECT_THAT(scn_error(one_sphere("sphere -0 0 0 0 0 0 0 1 1 1 0\n")), HasSubstr("expected a radius > 0"));
}

TEST(ScnErrors, ColourAndEmissionRanges) {
    EXPECT_THAT(scn_error(one_sphere("sphere 1  0 0 0  0 0 0  1 1.5 1  0\n")),
                StartsWith("t.scn:3:27: expected colour g in [0, 1], got '1.5'"));
    EXPECT_THAT(scn_error(one_sphere("sphere 1  0 0 0  0 0 0  1 1 -0.1  0\n")),
                StartsWith("t.scn:3:29: expected colour b in [0, 1], got '-0.1'"));
    EXPECT_THAT(scn_error(one_sphere("sphere 1  0 0 0  -1 0 0  1 1 1  0\n")),
                StartsWith("t.scn:3:18: expected emission r >= 0, got '-1'"));
}

TEST(ScnErrors, DegenerateCamera) {
    EXPECT_THAT(scn_error("camera 1 2 3  1 2 3\nsize 0\n"),
                StartsWith("t.scn:1:15: expected a camera target different from the camera position (degenerate camera)"));
    EXPECT_THAT(scn_error("camera 0 10 0  0 0 0\nsize 0\n"),
                StartsWith("t.scn:1:16: expected a view direction not parallel to the +y up vector (degenerate camera)"));
    EXPECT_THAT(scn_error("camera 5 0 5  5 7 5\nsize 0\n"), HasSubstr("not parallel to the +y up vector"));
}

TEST(ScnErrors, TruncatedLines) {
    EXPECT_THAT(scn_error("camera 0 0 10  0 0\n"), StartsWith("t.scn:1:19: expected camera target z, got end of line"));
    EXPECT_THAT(scn_error(std::string(kCamera) + "size\n"), StartsWith("t.scn:2:5: expected the sphere count, got end of line"));
    EXPECT_THAT(scn_error(one_sphere("sphere 1  0 0 0  0 0 0  1 1 1\n")),
                StartsWith("t.scn:3:30: expected the material code (0 diffuse, 1 mirror, 2 glass), got end of line"));
    EXPECT_THAT(scn_error(one_sphere("sphere 1  0 0 0  0 0")), StartsWith("t.scn:3:21: expected emission b, got end of line"));
    // A line cut short is not continued by the next one: statements are one per line.
    EXPECT_THAT(scn_error(one_sphere("sphere 1  0 0 0\n 0 0 0  1 1 1  0\n")), StartsWith("t.scn:3:16: expected emission r"));
    EXPECT_THAT(scn_error(one_sphere("sphere\n")), StartsWith("t.scn:3:7: expected the radius, got end of line"));
}

TEST(ScnErrors, TrailingGarbage) {
    EXPECT_THAT(scn_error("camera 0 0 10  0 0 0  7\nsize 0\n"),
                StartsWith("t.scn:1:23: expected end of line after the camera target, got '7'"));
    EXPECT_THAT(scn_error(std::string(kCamera) + "size 0 spheres\n"),
                StartsWith("t.scn:2:8: expected end of line after the sphere count, got 'spheres'"));
    EXPECT_THAT(scn_error(one_sphere("sphere 1  0 0 0  0 0 0  1 1 1  0 # the floor\n")),
                StartsWith("t.scn:3:34: expected end of line after the material code, got '#'"));
    EXPECT_THAT(scn_error(one_sphere("sphere 1 0 0 0 0 0 0 1 1 1 0\nend\n")),
                StartsWith("t.scn:4:1: expected 'sphere radius  px py pz  er eg eb  cr cg cb  m', got 'end'"));
    EXPECT_THAT(scn_error(std::string(kCamera) + "size 1\ncube 1 0 0 0 0 0 0 1 1 1 0\n"),
                StartsWith("t.scn:3:1: expected 'sphere radius  px py pz  er eg eb  cr cg cb  m', got 'cube'"));
    EXPECT_THAT(scn_error(std::string(kCamera) + "size 1\ncamera 0 0 1 0 0 0\n"),
                StartsWith("t.scn:3:1: expected 'sphere radius  px py pz  er eg eb  cr cg cb  m', got a second 'camera'"));
}

TEST(ScnErrors, BinaryJunk) {
    using namespace std::string_literals;
    EXPECT_THAT(scn_error("camera 0 0 10\0 0 0 0\n"s),
                StartsWith("t.scn:1:14: expected plain ASCII text, found byte 0x00 (a NUL byte: binary data?)"));
    EXPECT_THAT(scn_error("camera 0 0 10 0 0 0\nsize 0\n\x89PNG\x1a"s), StartsWith("t.scn:3:1: expected plain ASCII text, found byte 0x89"));
    EXPECT_THAT(scn_error("\x7f" "ELF\x02\x01\x01"s), StartsWith("t.scn:1:1: expected plain ASCII text, found byte 0x7F"));
    EXPECT_THAT(scn_error("camera 0 0 10 0 0 0\nsize 0\x1b[0m\n"s), StartsWith("t.scn:2:7: expected plain ASCII text, found byte 0x1B"));
}

TEST(ScnErrors, MessagesQuoteJunkPrintablyAndBriefly) {
    const std::string message = scn_error("camera " + std::string(200, 'x') + " 0 0 0 0 0\n");
    EXPECT_THAT(message, HasSubstr("got 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...'"));
    EXPECT_LT(message.size(), 200u);
}

TEST(ScnErrors, SourceNameIsUsed) {
    EXPECT_THAT(scn_error("", "<stdin>"), StartsWith("<stdin>:1:1: "));
    EXPECT_THAT(scn_error("", "scenes/cornell.scn"), StartsWith("scenes/cornell.scn:1:1: "));
}

}  // namespace
}  // namespace orb
