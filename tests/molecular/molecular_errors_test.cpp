// Every reader's errors: one message naming the file, the line and what was
// expected, never a crash or a hang.
#include <gtest/gtest.h>

#include "molecular_test_util.h"
#include "orb/scene/error.h"

namespace orb {
namespace {

struct ErrorCase {
    const char* name;
    const char* format;
    std::string bytes;
    std::string message;
};

std::string error_of(std::string_view format, const std::string& bytes, const std::string& source) {
    try {
        const auto frames = open_molecular_bytes(bytes, source, format, {});
        for (std::size_t k = 0; k < frames->frame_count(); ++k) frames->frame(k);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

void PrintTo(const ErrorCase& c, std::ostream* out) { *out << c.name; }

const std::string kDumpHead = "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n0 10\n";

class MolecularErrors : public testing::TestWithParam<ErrorCase> {};

TEST_P(MolecularErrors, NamesTheLineAndWhatWasExpected) {
    const ErrorCase& c = GetParam();
    EXPECT_EQ(error_of(c.format, c.bytes, "bad"), c.message);
}

INSTANTIATE_TEST_SUITE_P(
    Readers, MolecularErrors,
    testing::Values(
        ErrorCase{"XyzCountNotANumber", "xyz", "three\n\nC 0 0 0\n", "bad:1: expected the number of atoms of an XYZ frame, got 'three'"},
        ErrorCase{"XyzTruncated", "xyz", "3\n\nC 0 0 0\n",
                  "bad:1: the frame announces 3 atoms, but the file ends after 1 atom lines (truncated?)"},
        ErrorCase{"XyzBadCoordinate", "xyz", "1\n\nC 0 x 0\n", "bad:3: atom 1: expected a coordinate, got 'x'"},
        ErrorCase{"XyzTooFewColumns", "xyz", "1\n\nC 0 0\n",
                  "bad:3: atom 1: expected 4 columns (element x y z and the first atom's other columns), got 3: 'C 0 0'"},
        ErrorCase{"XyzNanCoordinate", "xyz", "1\n\nC 0 nan 0\n", "bad:3: atom 1: expected a coordinate, got 'nan'"},
        ErrorCase{"ExtendedXyzNoPositions", "xyz", "1\nProperties=species:S:1:x:R:1\nC 0\n",
                  "bad:2: Properties= has no pos:R:3 column (the atoms' positions)"},
        ErrorCase{"ExtendedXyzBadTriple", "xyz", "1\nProperties=species:S:1:pos:R\nC 0 0 0\n",
                  "bad:2: Properties='species:S:1:pos:R': expected name:type:count triples"},
        ErrorCase{"ExtendedXyzBadLattice", "xyz", "1\nLattice=\"1 0 0 0 1 0\"\nC 0 0 0\n",
                  "bad:2: Lattice='1 0 0 0 1 0': expected 9 numbers (the cell vectors a, b, c)"},
        ErrorCase{"DumpUnknownSection", "lammps-dump", "ITEM: TIMESTEP\n0\nITEM: WHATEVER\n",
                  "bad:3: expected a LAMMPS dump section (ITEM: TIMESTEP, ITEM: NUMBER OF ATOMS, ITEM: BOX BOUNDS, ITEM: ATOMS), got 'ITEM: WHATEVER'"},
        ErrorCase{"DumpNoPositions", "lammps-dump", kDumpHead + "ITEM: ATOMS id type vx\n1 1 0\n2 1 0\n",
                  "bad:9: ITEM: ATOMS names no positions: expected the columns x y z, xu yu zu, xs ys zs or xsu ysu zsu, got 'ATOMS id type vx'"},
        ErrorCase{"DumpWrongColumnCount", "lammps-dump", kDumpHead + "ITEM: ATOMS id x y z\n1 0 0 0\n2 0 0\n",
                  "bad:11: expected 4 columns (as ITEM: ATOMS names them), got 3: '2 0 0'"},
        ErrorCase{"DumpTruncated", "lammps-dump", kDumpHead + "ITEM: ATOMS id x y z\n1 0 0 0\n",
                  "bad:9: the frame has 2 atoms, but the file ends after 1 atom lines (truncated?)"},
        ErrorCase{"DumpBadNumber", "lammps-dump", kDumpHead + "ITEM: ATOMS id x y z\n1 0 0 0\n2 0 0 zz\n",
                  "bad:11: expected a number in column 'z', got 'zz'"},
        ErrorCase{"DumpNegativeRadius", "lammps-dump", kDumpHead + "ITEM: ATOMS id x y z radius\n1 0 0 0 1\n2 0 0 1 -1\n",
                  "bad:11: expected a radius > 0, got '-1'"},
        ErrorCase{"DumpValueBeyondFloat", "lammps-dump", kDumpHead + "ITEM: ATOMS id x y z c_e\n1 0 0 0 1\n2 0 0 1 1e39\n",
                  "bad:11: column 'c_e': 1e+39 does not fit a 32-bit float (about 3.4e38 at most)"},
        ErrorCase{"DumpDuplicateId", "lammps-dump", kDumpHead + "ITEM: ATOMS id x y z\n7 0 0 0\n7 0 0 1\n",
                  "bad:11: atom id 7 appears twice in the frame (first on line 10); each atom of a dump frame has its own id"},
        ErrorCase{"DumpAtomsBeforeCount", "lammps-dump", "ITEM: TIMESTEP\n0\nITEM: ATOMS id x y z\n",
                  "bad:3: ITEM: ATOMS before ITEM: NUMBER OF ATOMS"},
        ErrorCase{"GroCountNotANumber", "gro", "title\nmany\n", "bad:2: expected the number of atoms (the second line of a .gro frame), got 'many'"},
        ErrorCase{"GroShortAtomLine", "gro", "t\n1\n    1MET      N    1   2.493\n   1 1 1\n",
                  "bad:3: atom 1: expected the fixed columns of a .gro atom line (residue number 1-5, residue name 6-10, atom name 11-15, atom number 16-20, x y z in 8 columns each from 21), got '    1MET      N    1   2.493'"},
        ErrorCase{"GroBadBox", "gro", "t\n1\n    1MET      N    1   2.493   2.495   1.887\n   1 1\n",
                  "bad:4: expected the box: 3 or 9 numbers (nm), got '   1 1'"},
        ErrorCase{"GroTruncated", "gro", "t\n2\n    1MET      N    1   2.493   2.495   1.887\n",
                  "bad:2: the frame announces 2 atoms and a box line, but the file ends 1 lines later (truncated?)"},
        ErrorCase{"EmptyXyz", "xyz", "", "bad: no frames (the file holds no atoms)"},
        ErrorCase{"FirstFrameWithoutAtoms", "xyz", "0\n\n", "bad: frame 1 has no atoms"}),
    [](const testing::TestParamInfo<ErrorCase>& info) { return std::string(info.param.name); });

TEST(MolecularErrorsPdb, GemmiMessagesNameTheFile) {
    // gemmi would read x.000 as 0: the coordinates are checked before it reads them.
    EXPECT_EQ(error_of("pdb", "ATOM      1  N   SER A   1       1.000   x.000   1.000\n", "bad.pdb"),
              "bad.pdb:1: expected the atom's y in columns 39-46, got 'x.000'");
    EXPECT_EQ(error_of("pdb", "ATOM      1  N   SER A   1       1.000\n", "bad.pdb"),
              "bad.pdb:1: expected the atom's y in columns 39-46, got ''");
    EXPECT_EQ(error_of("mmcif", "data_x\nloop_\n_atom_site.id\n", "bad.cif").substr(0, 7), "bad.cif");
    EXPECT_EQ(error_of("pdb", "REMARK nothing\n", "empty.pdb"), "empty.pdb: no atoms (no model in the file)");
}

// The refused files of chemfiles' tests-data.
TEST(MolecularErrorsFiles, RealBadFilesAreRefusedAtTheirLine) {
    const struct {
        const char* name;
        const char* format;
        const char* message;
    } cases[] = {
        {"bad-helium.xyz", "xyz", ":1: the frame announces 8 atoms, but the file ends after 4 atom lines (truncated?)"},
        {"bad-atom-not-enough-lines.lammpstrj", "lammps-dump", ":9: the frame has 3 atoms, but the file ends after 2 atom lines (truncated?)"},
        {"bad-box-not-numbers.lammpstrj", "lammps-dump", ":6: expected lo hi of the box, got 'DUMMY'"},
        {"bad-timestep-item-name.lammpstrj", "lammps-dump",
         ":1: expected a LAMMPS dump section (ITEM: TIMESTEP, ITEM: NUMBER OF ATOMS, ITEM: BOX BOUNDS, ITEM: ATOMS), got 'ITEM: DUMMY'"},
        {"truncated.gro", "gro", ":2: the frame announces 1405 atoms and a box line, but the file ends 556 lines later (truncated?)"},
        {"bad-extended-bad-properties.xyz", "xyz", ":3: atom 1: expected a coordinate, got 'H'"},
    };
    for (const auto& c : cases) {
        const std::string path = test::data_path(c.name);
        try {
            const auto frames = open_molecular_file(path, c.format, {});
            for (std::size_t k = 0; k < frames->frame_count(); ++k) frames->frame(k);
            ADD_FAILURE() << c.name << ": accepted";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), path + c.message);
        }
    }
}

}  // namespace
}  // namespace orb
