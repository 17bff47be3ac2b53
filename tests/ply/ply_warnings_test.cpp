// What the PLY reader reads past is named, never dropped silently: vertex
// properties it does not read, other elements, bytes after the last element,
// and header lines without a keyword (read as comments). The headers below
// are those real writers produce.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "orb/import/ply.h"
#include "ply_builder.h"

namespace orb {
namespace {

using test::make_ply;
using test::PlyTestElement;
using test::PlyTestProperty;

const std::vector<std::string> kEncodings{"ascii", "binary_little_endian", "binary_big_endian"};

std::vector<PlyTestProperty> floats(const std::vector<std::string>& names) {
    std::vector<PlyTestProperty> properties;
    for (const std::string& name : names) properties.push_back({"float", name, ""});
    return properties;
}

TEST(PlyWarnings, EveryUnreadPropertyAndElementIsNamedInEveryEncoding) {
    // The Stanford scans' layout (bun_zipper.ply): confidence and intensity per vertex, a face list.
    const PlyTestElement vertex{"vertex", floats({"x", "y", "z", "confidence", "intensity"}),
                                {{0, 0, 0, 1, 0.5}, {1, 0, 0, 1, 0.25}, {0, 1, 0, 0.5, 1}}};
    const PlyTestElement face{"face", {{"int", "vertex_indices", "uchar"}}, {{3, 0, 1, 2}}};
    for (const std::string& encoding : kEncodings) {
        const PlyImportResult result = import_ply(make_ply(encoding, {vertex, face}), "bun.ply");
        // The faces are lost; confidence and intensity are kept as the spheres' properties.
        EXPECT_EQ(result.warnings, (std::vector<std::string>{"bun.ply: ignored elements: face (1 row)"})) << encoding;
        EXPECT_EQ(result.notices, (std::vector<std::string>{"bun.ply: vertex properties kept as sphere properties (for "
                                                            "--color-by, --radius-by): confidence, intensity"}));
        ASSERT_EQ(result.scene.sphere_attributes.properties.size(), 2u);
        EXPECT_EQ(result.scene.sphere_attributes.properties[1].values, (std::vector<float>{0.5f, 0.25f, 1, 0, 0}));
        EXPECT_EQ(result.scene.spheres.size(), 3u + 2u);
    }
}

TEST(PlyWarnings, AGaussianSplattingFileIsRecognisedAndItsFieldsListedShortly) {
    // The vertex layout 3D Gaussian splatting writes (graphdeco-inria/gaussian-splatting,
    // GaussianModel.save_ply): position, normal, 3 + 45 spherical-harmonic coefficients,
    // opacity, 3 log-scales and a rotation quaternion.
    std::vector<std::string> names{"x", "y", "z", "nx", "ny", "nz", "f_dc_0", "f_dc_1", "f_dc_2"};
    for (int i = 0; i < 45; ++i) names.push_back("f_rest_" + std::to_string(i));
    for (const char* name : {"opacity", "scale_0", "scale_1", "scale_2", "rot_0", "rot_1", "rot_2", "rot_3"})
        names.push_back(name);
    std::vector<double> row(names.size(), 0.0);
    std::vector<double> other = row;
    other[0] = 1;
    const PlyImportResult result =
        import_ply(make_ply("binary_little_endian", {{"vertex", floats(names), {row, other}}}), "splats.ply");
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_EQ(result.warnings[0],
              "splats.ply: a 3D Gaussian splatting file: Orb renders neither its spherical-harmonic colours nor its "
              "log-scales, so its points are grey, sized by --radius or the derived radius (its fields are kept as "
              "sphere properties)");
    ASSERT_EQ(result.notices.size(), 1u);
    EXPECT_EQ(result.notices[0],
              "splats.ply: vertex properties kept as sphere properties (for --color-by, --radius-by): nx, ny, nz, "
              "f_dc_0..2, f_rest_0..44, opacity, scale_0..2, rot_0..3");
    EXPECT_EQ(result.scene.spheres.size(), 2u + 2u);
}

TEST(PlyWarnings, BytesAfterTheLastElementAreCounted) {
    const PlyTestElement vertex{"vertex", floats({"x", "y", "z"}), {{0, 0, 0}}};
    // Only white space after ASCII data is nothing; anything else, or any byte after binary data, is named.
    EXPECT_TRUE(import_ply(make_ply("ascii", {vertex}) + "\n \n", "c.ply").warnings.empty());
    EXPECT_EQ(import_ply(make_ply("ascii", {vertex}) + "\n7 8 9\n", "c.ply").warnings,
              std::vector<std::string>{"c.ply: ignored 6 bytes after the last element"});
    EXPECT_EQ(import_ply(make_ply("binary_big_endian", {vertex}) + "\n", "c.ply").warnings,
              std::vector<std::string>{"c.ply: ignored 1 byte after the last element"});
}

TEST(PlyWarnings, HeaderLinesWithoutAKeywordAreReadAsCommentsWithANotice) {
    // Blender 2.4x's exporter wrote its credit line without "comment"; some writers leave a blank line.
    const std::string bytes =
        "ply\nformat ascii 1.0\nCreated by Blender3D 249 - www.blender.org, source file: lamp.blend\n\n"
        "element vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n";
    const PlyImportResult result = import_ply(bytes, "lamp.ply");
    EXPECT_TRUE(result.warnings.empty());
    EXPECT_EQ(result.notices, std::vector<std::string>{
                                  "lamp.ply: header lines 3 (\"Created by Blender3D 249 - www.blender.org, source file: "
                                  "lamp.blend\"), 4 (\"\") have no PLY keyword and were read as comments"});
    ASSERT_EQ(result.scene.spheres.size(), 1u + 2u);
    EXPECT_EQ(result.scene.spheres[0].center, (Vec3{1, 2, 3}));
}

TEST(PlyWarnings, AFileWithoutPointsSaysWhyInsteadOfFailing) {
    // import_ply hands the reason on; import_scene refuses the scene unless --allow-empty.
    const PlyImportResult empty = import_ply(make_ply("ascii", {{"vertex", floats({"x", "y", "z"}), {}}}), "e.ply");
    EXPECT_EQ(empty.no_spheres, "its 'vertex' element has 0 rows");
    EXPECT_TRUE(empty.scene.spheres.empty());
    EXPECT_EQ(import_ply("ply\nformat ascii 1.0\nend_header\n", "h.ply").no_spheres, "it has no 'vertex' element");
}

}  // namespace
}  // namespace orb
