// Every way a PLY file can be broken gets one message naming the file and
// the header line or the vertex.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "orb/scene/error.h"
#include "orb/import/import.h"
#include "orb/import/ply.h"
#include "ply_builder.h"

namespace orb {
namespace {

using ::testing::HasSubstr;

// As the tools read it: a file without points is refused too.
std::string error_of(const std::string& bytes) {
    try {
        ImportOptions options;
        options.format = "ply";
        import_scene(bytes, "bad.ply", ".", options);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

const std::string kXyzHeader = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n";

struct ErrorCase {
    const char* label;
    std::string bytes;
    std::string message;
};

class PlyError : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(PlyError, NamesTheFileAndWhere) {
    EXPECT_EQ(error_of(GetParam().bytes), GetParam().message);
}

std::string binary_xyz(std::size_t declared, const std::string& data) {
    return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(declared) +
           "\nproperty float x\nproperty float y\nproperty float z\nend_header\n" + data;
}

std::string float_bytes(std::initializer_list<float> values) {
    std::string out;
    for (float v : values) out.append(reinterpret_cast<const char*>(&v), sizeof v);
    return out;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, PlyError,
    ::testing::Values(
        ErrorCase{"BadMagic", "plx\nformat ascii 1.0\n", "bad.ply:1: not a PLY file (it must start with the line \"ply\")"},
        ErrorCase{"BadFormatLine", "ply\nformat ascii 2.0\nend_header\n", "bad.ply:2: unsupported PLY version '2.0' (expected 1.0)"},
        ErrorCase{"UnknownEncoding", "ply\nformat binary_middle_endian 1.0\nend_header\n",
                  "bad.ply:2: unknown encoding 'binary_middle_endian' (expected ascii, binary_little_endian or binary_big_endian)"},
        // A line without a keyword is read as a comment (Blender 2.4x wrote one); the error it leads to names it.
        ErrorCase{"MisspeltElement", "ply\nformat ascii 1.0\nelemnt vertex 1\nend_header\n",
                  "bad.ply: no spheres: it has no 'vertex' element (line 3 (\"elemnt vertex 1\") has no PLY keyword and "
                  "was read as a comment); --allow-empty accepts a scene without spheres"},
        ErrorCase{"MisspeltProperty", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproprety float z\nend_header\n1 2 3\n",
                  "bad.ply:3: element 'vertex' has no 'z' property (x, y and z are required) (line 6 (\"proprety float z\") "
                  "has no PLY keyword and was read as a comment)"},
        ErrorCase{"MisspeltPropertyBeforeElement", "ply\nformat ascii 1.0\nelemnt vertex 1\nproperty float x\nend_header\n",
                  "bad.ply:4: a property before any \"element\" line (line 3 (\"elemnt vertex 1\") has no PLY keyword and "
                  "was read as a comment)"},
        ErrorCase{"UnknownPropertyType", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float16 x\nend_header\n",
                  "bad.ply:4: unknown property type 'float16' (expected char, uchar, short, ushort, int, uint, float, "
                  "double or int8 ... float64)"},
        ErrorCase{"FloatListCount", "ply\nformat ascii 1.0\nelement face 1\nproperty list float int v\nend_header\n",
                  "bad.ply:4: a list count type must be an integer type, got 'float'"},
        ErrorCase{"PropertyBeforeElement", "ply\nformat ascii 1.0\nproperty float x\nend_header\n",
                  "bad.ply:3: a property before any \"element\" line"},
        ErrorCase{"NoEndHeader", "ply\nformat ascii 1.0\nelement vertex 1\n",
                  "bad.ply:4: the header ends without an \"end_header\" line"},
        ErrorCase{"NoFormat", "ply\nelement vertex 0\nend_header\n", "bad.ply:3: the header has no \"format\" line"},
        ErrorCase{"MissingZ", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n",
                  "bad.ply:3: element 'vertex' has no 'z' property (x, y and z are required)"},
        ErrorCase{"ListCoordinate", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty list uchar float z\nend_header\n",
                  "bad.ply:6: vertex property 'z' must be a single value, not a list"},
        ErrorCase{"NoVertexElement", "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int v\nend_header\n",
                  "bad.ply: no spheres: it has no 'vertex' element; --allow-empty accepts a scene without spheres"},
        ErrorCase{"EmptyCloud", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
                  "bad.ply: no spheres: its 'vertex' element has 0 rows; --allow-empty accepts a scene without spheres"},
        ErrorCase{"CountOverflows", "ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\nend_header\n",
                  "bad.ply:3: element 'vertex' count 99999999999999999999999 overflows"},
        ErrorCase{"NegativeCount", "ply\nformat ascii 1.0\nelement vertex -1\nend_header\n",
                  "bad.ply:3: element 'vertex' count must be a non-negative integer, got '-1'"},
        ErrorCase{"CountLargerThanBinaryFile", binary_xyz(1000000, float_bytes({1, 2, 3})),
                  "bad.ply:3: element 'vertex' declares 1000000 rows of at least 12 bytes, more than the 12 bytes of "
                  "data left in the file"},
        ErrorCase{"CountTimesRowOverflows", binary_xyz(2305843009213693952ull, float_bytes({1, 2, 3})),
                  "bad.ply:3: element 'vertex' declares 2305843009213693952 rows of at least 12 bytes, more than the "
                  "12 bytes of data left in the file"},
        ErrorCase{"TruncatedAscii", kXyzHeader + "end_header\n1 2 3\n4 5\n",
                  "bad.ply: vertex 1 property 'z': the data ends early (the file is truncated)"},
        ErrorCase{"TruncatedBinaryList",
                  "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty "
                  "float z\nelement face 1\nproperty list uchar int v\nend_header\n" + float_bytes({1, 2, 3}) + "\x03" + std::string("\x01\0\0\0", 4),
                  "bad.ply: face 0 property 'v': the data ends early (the file is truncated)"},
        ErrorCase{"NanCoordinate", kXyzHeader + "end_header\n1 2 3\nnan 5 6\n", "bad.ply: vertex 1 property 'x': must be finite, got nan"},
        ErrorCase{"InfCoordinateBinary", binary_xyz(1, float_bytes({1, std::numeric_limits<float>::infinity(), 3})),
                  "bad.ply: vertex 0 property 'y': must be finite, got inf"},
        ErrorCase{"DoubleOverflowAscii", kXyzHeader + "end_header\n1 2 3\n4 5 1e999\n",
                  "bad.ply: vertex 1 property 'z': '1e999' overflows a double"},
        ErrorCase{"NotANumber", kXyzHeader + "end_header\n1 2 3\n4 abc 6\n", "bad.ply: vertex 1 property 'y': expected a number, got 'abc'"},
        ErrorCase{"IntegerOutOfRange",
                  "ply\nformat ascii 1.0\nelement vertex 1\nproperty uchar x\nproperty float y\nproperty float z\nend_header\n256 0 0\n",
                  "bad.ply: vertex 0 property 'x': expected a uchar, got '256'"},
        ErrorCase{"NegativeRadius",
                  "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nproperty float radius\nend_header\n0 0 0 1\n1 1 1 -1\n",
                  "bad.ply: vertex 1 property 'radius': must be > 0, got -1"},
        ErrorCase{"ColourOutOfRange",
                  "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty float red\nproperty float green\nproperty float blue\nend_header\n0 0 0 1 2 0\n",
                  "bad.ply: vertex 0 property 'green': colour must be in [0, 1] (0 .. 255 for uchar), got 2"},
        ErrorCase{"NegativeListCount",
                  "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty list char float extra\nend_header\n0 0 0 -2\n",
                  "bad.ply: vertex 0 property 'extra': a negative list count (-2)"}),
    [](const ::testing::TestParamInfo<ErrorCase>& info) { return std::string(info.param.label); });

}  // namespace
}  // namespace orb

namespace orb {
namespace {

TEST(PlyErrors, ACloudTooFarFromTheOriginForItsSize) {
    const std::string bytes =
        "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\nproperty double z\nend_header\n"
        "0 0 1e30\n";
    EXPECT_EQ(error_of(bytes),
              "bad.ply: the cloud lies too far from the origin for its size (radius 1.4142135623730951 around 0, 0, "
              "1e+30): no camera can be placed in double precision; move it or pass a larger --radius");
}

}  // namespace
}  // namespace orb
