// Reading PLY data: the three encodings agree, every scalar type, colour
// encodings, and elements and properties the importer does not use.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "orb/import/import.h"
#include "orb/import/importers.h"
#include "orb/import/ply.h"
#include "ply_builder.h"

namespace orb {
namespace {

using test::make_ply;
using test::PlyTestElement;

const std::vector<std::string> kEncodings{"ascii", "binary_little_endian", "binary_big_endian"};

// A little cloud with radii, uchar colours, normals, and faces with lists
// before and after the vertices.
std::vector<PlyTestElement> rich_cloud() {
    PlyTestElement header_element{"camera", {{"float", "view_x", ""}, {"int", "tags", "uchar"}}, {{1.5, 2, 7, 8}}};
    PlyTestElement vertex{"vertex",
                          {{"float", "x", ""},
                           {"float", "y", ""},
                           {"float", "z", ""},
                           {"float", "nx", ""},
                           {"float", "ny", ""},
                           {"float", "nz", ""},
                           {"float", "radius", ""},
                           {"uchar", "red", ""},
                           {"uchar", "green", ""},
                           {"uchar", "blue", ""},
                           {"float", "confidence", "ushort"}},
                          {{0, 0, 0, 0, 1, 0, 0.5, 255, 0, 0, 2, 0.25, 0.75},
                           {1, 2, 3, 1, 0, 0, 0.25, 0, 255, 0, 0},
                           {-4, 5.5, -6.25, 0, 0, 1, 1, 255, 0, 0, 1, 1}}};
    PlyTestElement faces{"face", {{"int", "vertex_indices", "uchar"}, {"uchar", "flags", ""}}, {{3, 0, 1, 2, 9}, {0, 1}}};
    return {header_element, vertex, faces};
}

TEST(PlyRead, AsciiAndBothBinaryByteOrdersGiveTheSameScene) {
    const Scene ascii = import_ply(make_ply("ascii", rich_cloud()), "cloud.ply").scene;
    ASSERT_EQ(ascii.spheres.size(), 3u + 2u);  // three points, two default lights
    EXPECT_EQ(ascii.spheres[1].center, (Vec3{1, 2, 3}));
    EXPECT_EQ(ascii.spheres[2].center, (Vec3{-4, 5.5, -6.25}));
    EXPECT_EQ(ascii.spheres[0].radius, 0.5);
    EXPECT_EQ(ascii.spheres[1].radius, 0.25);
    for (const std::string& encoding : {std::string("binary_little_endian"), std::string("binary_big_endian")})
        EXPECT_EQ(import_ply(make_ply(encoding, rich_cloud()), "cloud.ply").scene, ascii) << encoding;
}

TEST(PlyRead, ContentIsRecognisedAsPly) {
    for (const std::string& encoding : kEncodings) {
        const std::string bytes = make_ply(encoding, rich_cloud());
        ASSERT_NE(recognise_scene(bytes), nullptr);
        EXPECT_EQ(recognise_scene(bytes)->name, "ply");
        EXPECT_EQ(import_scene(bytes, "cloud.ply", ".").scene, import_ply(bytes, "cloud.ply").scene);
    }
    EXPECT_EQ(find_scene_importer("ply"), recognise_scene(make_ply("ascii", rich_cloud())));
}

TEST(PlyRead, WindowsLineEndingsInTheHeader) {
    std::string bytes = make_ply("ascii", rich_cloud());
    std::string crlf;
    for (char c : bytes) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    EXPECT_EQ(import_ply(crlf, "cloud.ply").scene, import_ply(bytes, "cloud.ply").scene);
}

TEST(PlyRead, EveryScalarTypeAndAliasReadsItsValues) {
    const std::vector<std::pair<std::string, std::vector<double>>> types{
        {"char", {-100, 0, 127}},         {"int8", {-128, 5, 7}},         {"uchar", {0, 200, 255}},
        {"uint8", {1, 2, 3}},             {"short", {-32768, 0, 32767}},  {"int16", {-3, 4, 5}},
        {"ushort", {0, 40000, 65535}},    {"uint16", {6, 7, 8}},          {"int", {-2147483648.0, 0, 2147483647}},
        {"int32", {-9, 10, 11}},          {"uint", {0, 3000000000.0, 4294967295.0}},
        {"uint32", {12, 13, 14}},         {"float", {0.5, -1.25, 1e15}},  {"float32", {3.5, 4.5, -5.5}},
        {"double", {0.1, -9.75e14, 1e-300}}, {"float64", {0.3, 0.7, 123456789.125}},
    };
    for (const auto& [type, values] : types) {
        for (const std::string& encoding : kEncodings) {
            const PlyTestElement vertex{"vertex", {{type, "x", ""}, {type, "y", ""}, {type, "z", ""}}, {values}};
            // A radius as large as the largest value keeps the automatic camera placeable
            // (and within the scene's float range, 1e18).
            const Scene scene = import_ply(make_ply(encoding, {vertex}), "types.ply", {.radius = 1e15}).scene;
            Vec3 expected{values[0], values[1], values[2]};
            if (type == "float" || type == "float32")
                for (double& v : expected) v = static_cast<float>(v);
            EXPECT_EQ(scene.spheres.at(0).center, expected) << type << " " << encoding;
        }
    }
}

// The point's own colour (Scene::sphere_attributes), as doubles.
Vec3 point_color(const Scene& scene, std::size_t point) {
    const std::vector<float>& colors = scene.sphere_attributes.colors;
    return {colors.at(3 * point), colors.at(3 * point + 1), colors.at(3 * point + 2)};
}

TEST(PlyRead, UcharAndFloatColoursMeanTheSame) {
    const PlyTestElement bytes{"vertex",
                               {{"float", "x", ""}, {"float", "y", ""}, {"float", "z", ""},
                                {"uchar", "red", ""}, {"uchar", "green", ""}, {"uchar", "blue", ""}},
                               {{0, 0, 0, 255, 128, 0}, {1, 0, 0, 10, 20, 30}}};
    const PlyTestElement floats{"vertex",
                                {{"float", "x", ""}, {"float", "y", ""}, {"float", "z", ""},
                                 {"double", "red", ""}, {"double", "green", ""}, {"double", "blue", ""}},
                                {{0, 0, 0, 1, 128 / 255.0, 0}, {1, 0, 0, 10 / 255.0, 20 / 255.0, 30 / 255.0}}};
    for (const std::string& encoding : kEncodings) {
        const Scene from_bytes = import_ply(make_ply(encoding, {bytes}), "c.ply").scene;
        const Scene from_floats = import_ply(make_ply(encoding, {floats}), "c.ply").scene;
        EXPECT_EQ(point_color(from_bytes, 0), point_color(from_floats, 0)) << encoding;
        EXPECT_EQ(point_color(from_bytes, 1), point_color(from_floats, 1)) << encoding;
    }
    // sRGB-encoded display values become linear reflectance: 255 -> 1, 128 -> ~0.2158, 0 -> 0.
    const Vec3 c = point_color(import_ply(make_ply("ascii", {bytes}), "c.ply").scene, 0);
    EXPECT_DOUBLE_EQ(c[0], 1.0);
    EXPECT_NEAR(c[1], 0.2158605, 1e-6);
    EXPECT_EQ(c[2], 0.0);
}

TEST(PlyRead, OtherColourNamesAndSixteenBitColours) {
    const PlyTestElement short_names{"vertex",
                                     {{"float", "x", ""}, {"float", "y", ""}, {"float", "z", ""},
                                      {"uchar", "r", ""}, {"uchar", "g", ""}, {"uchar", "b", ""}},
                                     {{0, 0, 0, 255, 0, 255}}};
    const PlyTestElement diffuse{"vertex",
                                 {{"float", "x", ""}, {"float", "y", ""}, {"float", "z", ""},
                                  {"ushort", "diffuse_red", ""}, {"ushort", "diffuse_green", ""},
                                  {"ushort", "diffuse_blue", ""}},
                                 {{0, 0, 0, 65535, 0, 65535}}};
    const Vec3 magenta{1, 0, 1};
    EXPECT_EQ(point_color(import_ply(make_ply("ascii", {short_names}), "c.ply").scene, 0), magenta);
    EXPECT_EQ(point_color(import_ply(make_ply("binary_big_endian", {diffuse}), "c.ply").scene, 0), magenta);
}

TEST(PlyRead, ScaleStandsForRadius) {
    const PlyTestElement vertex{"vertex", {{"float", "x", ""}, {"float", "y", ""}, {"float", "z", ""}, {"double", "scale", ""}},
                                {{0, 0, 0, 0.125}}};
    EXPECT_EQ(import_ply(make_ply("binary_little_endian", {vertex}), "s.ply").scene.spheres.at(0).radius, 0.125);
}

TEST(PlyRead, ElementsWithoutPropertiesAndTrailingDataAreFine) {
    std::string bytes =
        "ply\nformat ascii 1.0\nobj_info from a scanner\nelement empty 5\nelement vertex 2\nproperty float x\n"
        "property float y\nproperty float z\nend_header\n1 2 3\n\t4 5 6 7 8\n";
    const Scene scene = import_ply(bytes, "t.ply", {.radius = 1}).scene;
    ASSERT_EQ(scene.spheres.size(), 4u);
    EXPECT_EQ(scene.spheres[1].center, (Vec3{4, 5, 6}));
}

}  // namespace
}  // namespace orb
