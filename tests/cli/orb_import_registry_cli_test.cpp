// orb-import reads its formats from the table of importers
// (orb/import/importers.h): --list-formats shows it, docs/orb-import.md shows
// the same listing, --from takes its words, and an option of one format given
// for an input of another is named in a warning rather than dropped.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "import_cli_fixture.h"
#include "orb/import/importers.h"
#include "run_process.h"

namespace orb {
namespace {

using test::ProcessResult;
using ::testing::HasSubstr;
using ::testing::IsEmpty;
using ::testing::StartsWith;

const std::string kCloud =
    "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n"
    "0 0 0\n1 0 0\n";

class OrbImportRegistryCli : public test::ImportCliFixture {};

TEST_F(OrbImportRegistryCli, ListFormatsShowsEveryImporter) {
    const ProcessResult r = run({"--list-formats"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.err, IsEmpty());
    EXPECT_THAT(r.out, StartsWith("FORMAT "));
    for (const SceneImporter& importer : scene_importers()) {
        std::string row_start = "\n";  // built up: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string
        row_start += importer.name;
        EXPECT_THAT(r.out, HasSubstr(row_start)) << importer.name;
        EXPECT_THAT(r.out, HasSubstr(std::string(importer.description) + "\n")) << importer.name;
        for (std::string_view alias : importer.aliases) EXPECT_THAT(r.out, HasSubstr(", " + std::string(alias)));
    }
    EXPECT_THAT(files(), IsEmpty());
}

TEST_F(OrbImportRegistryCli, TheDocShowsTheListing) {
    std::ifstream in(ORB_IMPORT_DOC);
    ASSERT_TRUE(in) << ORB_IMPORT_DOC;
    const std::string doc{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const ProcessResult r = run({"--list-formats"});
    EXPECT_THAT(doc, HasSubstr("```\n$ orb-import --list-formats\n" + r.out + "```\n"))
        << "docs/orb-import.md must show orb-import --list-formats as it is:\n" << r.out;
}

TEST_F(OrbImportRegistryCli, FromTakesEveryWordAndNamesThemWhenWrong) {
    write("cloud.ply", kCloud);
    const ProcessResult r = run({"-", "--from", "ply", "-o", "out.json"}, kCloud);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const ProcessResult wrong = run({"cloud.ply", "--from", "obj"});
    EXPECT_EQ(wrong.exit_code, 2);
    for (const std::string& word : scene_format_words()) EXPECT_THAT(wrong.err, HasSubstr(word));
}

TEST_F(OrbImportRegistryCli, OptionsOfAnotherFormatAreNamed) {
    write("cloud.ply", kCloud);
    const ProcessResult r = run({"cloud.ply", "--gltf-scene", "0", "--light-units", "radiometric", "-o", "out.json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("orb-import: warning: cloud.ply: ignored --gltf-scene (glTF input), --light-units (glTF "
                                 "input): the input is read as ply"));
    // orb-import's own --frame belongs to the molecular readers' group too.
    const ProcessResult frame = run({"cloud.ply", "--frame", "2", "-o", "out.json"});
    EXPECT_EQ(frame.exit_code, 0) << frame.err;
    EXPECT_THAT(frame.err, HasSubstr("ignored --frame (Molecule input): the input is read as ply"));
    const ProcessResult own = run({"cloud.ply", "--radius", "0.1", "-o", "out.json"});
    EXPECT_EQ(own.exit_code, 0) << own.err;
    EXPECT_THAT(own.err, ::testing::Not(HasSubstr("ignored --"))) << own.err;
}

}  // namespace
}  // namespace orb
