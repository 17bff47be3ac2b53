// Each reader on real files (tests/data/chemfiles-tests-data/README.md):
// the counts, positions and per-atom values the files hold, read back
// independently from their text here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "molecular_test_util.h"
#include "orb/import/elements.h"
#include "orb/scene/scene_binary.h"
#include "orb/scene/scene_json.h"
#include "orb/import/sphere_styling.h"

namespace orb {
namespace {

using test::atom_count;
using test::label_of;
using test::property;
using test::read_data;

std::unique_ptr<FrameSource> open(const std::string& name, std::string_view format, MolecularImportOptions options = {}) {
    return open_molecular_file(test::data_path(name), format, options);
}

// ATOM/HETATM records of a PDB file's first model, as fixed columns.
struct PdbAtom {
    std::string element, chain;
    double x, y, z, b;
};
std::vector<PdbAtom> pdb_atoms(const std::string& text) {
    std::vector<PdbAtom> atoms;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.starts_with("ENDMDL")) break;
        if (!line.starts_with("ATOM  ") && !line.starts_with("HETATM")) continue;
        std::string element = line.size() >= 78 ? line.substr(76, 2) : "";
        element.erase(0, element.find_first_not_of(' '));
        atoms.push_back({element, line.substr(21, 1), std::stod(line.substr(30, 8)), std::stod(line.substr(38, 8)),
                         std::stod(line.substr(46, 8)), std::stod(line.substr(60, 6))});
    }
    return atoms;
}

TEST(MolecularFiles, HaemoglobinPdbAtomsElementsChainsAndBFactors) {
    const auto frames = open("4hhb.pdb", "pdb");
    ASSERT_EQ(frames->frame_count(), 1u);
    const Scene scene = frames->frame(0);
    validate_scene(scene, "4hhb.pdb");
    const std::vector<PdbAtom> expected = pdb_atoms(read_data("4hhb.pdb"));
    ASSERT_EQ(atom_count(scene), expected.size());  // 4HHB has no alternate locations
    const SphereProperty& element = *property(scene, "element");
    const SphereProperty& chain = *property(scene, "chain");
    const SphereProperty& b = *property(scene, "b_factor");
    for (std::size_t i = 0; i < expected.size(); ++i) {
        ASSERT_EQ(scene.spheres[i].center, (Vec3{expected[i].x, expected[i].y, expected[i].z})) << i;
        ASSERT_EQ(label_of(element, i), find_element(expected[i].element)->symbol) << i;
        ASSERT_EQ(label_of(chain, i), expected[i].chain) << i;
        ASSERT_FLOAT_EQ(b.values[i], static_cast<float>(expected[i].b)) << i;
        ASSERT_EQ(scene.spheres[i].radius, find_element(expected[i].element)->vdw_radius) << i;
        const Vec3 color = element_color(*find_element(expected[i].element));
        for (int c = 0; c < 3; ++c) ASSERT_FLOAT_EQ(scene.sphere_attributes.colors[3 * i + c], static_cast<float>(color[c]));
    }
    EXPECT_EQ(std::set<std::string>(chain.labels.begin(), chain.labels.end()),
              (std::set<std::string>{"A", "B", "C", "D"}));
    // One shared material for the atoms (their colours are per sphere), then the two lights.
    EXPECT_EQ(scene.materials.size(), 3u);
    for (std::size_t i = 0; i < expected.size(); ++i) ASSERT_EQ(scene.spheres[i].material, 0u);
    EXPECT_GT(scene.materials[1].emission[0], 0);
}

TEST(MolecularFiles, Cryst1IsTheCell) {
    // CRYST1   63.150   83.590   53.800  90.00  99.34  90.00. 4HHB's SCALEn records place the cell in the
    // atoms' own frame (not the standard one with a along x), so its edges are checked by length and angle.
    const Scene scene = open("4hhb.pdb", "pdb", {.cell = true})->frame(0);
    const auto first = std::find_if(scene.spheres.begin(), scene.spheres.end(), [](const Sphere& s) { return s.material == 1; });
    ASSERT_NE(first, scene.spheres.end());
    EXPECT_EQ(scene.materials[1].name, "cell");
    // The 8 corners come first, in the order (i, j, k) of origin + i a + j b + k c.
    const Vec3 origin = first[0].center, a = first[4].center, b = first[2].center, c = first[1].center;
    const auto edge = [&origin](const Vec3& p) { return Vec3{p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]}; };
    const auto length = [](const Vec3& v) { return std::hypot(v[0], v[1], v[2]); };
    const auto angle = [&](const Vec3& u, const Vec3& v) {
        return std::acos((u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / (length(u) * length(v))) * 180 / 3.14159265358979323846;
    };
    // SCALEn holds 6 decimals: lengths to 1e-3 relative, angles to 0.01 degree.
    EXPECT_NEAR(length(edge(a)), 63.15, 0.06);
    EXPECT_NEAR(length(edge(b)), 83.59, 0.08);
    EXPECT_NEAR(length(edge(c)), 53.80, 0.05);
    EXPECT_NEAR(angle(edge(a), edge(c)), 99.34, 0.01);
    EXPECT_NEAR(angle(edge(a), edge(b)), 90.0, 0.01);
    EXPECT_NEAR(angle(edge(b), edge(c)), 90.0, 0.01);
}

TEST(MolecularFiles, MmcifGivesTheSameAtomsAsPdb) {
    const Scene pdb = open("4hhb.pdb", "pdb")->frame(0);
    const Scene cif = open("4hhb.cif", "mmcif")->frame(0);
    ASSERT_EQ(atom_count(pdb), atom_count(cif));
    for (std::size_t i = 0; i < atom_count(pdb); ++i) ASSERT_EQ(pdb.spheres[i].center, cif.spheres[i].center) << i;
    EXPECT_EQ(pdb.camera, cif.camera);
}

TEST(MolecularFiles, NmrModelsAreFramesUnderOneCamera) {
    const auto frames = open("2hkb.pdb", "pdb");
    ASSERT_EQ(frames->frame_count(), 10u);
    const Scene first = frames->frame(0), last = frames->frame(9);
    EXPECT_EQ(first.camera, last.camera);
    EXPECT_EQ(first.spheres.back(), last.spheres.back());  // the fill light
    ASSERT_EQ(atom_count(first), atom_count(last));
    EXPECT_NE(first.spheres[0].center, last.spheres[0].center);
    // Without hydrogens: fewer atoms, none of them H.
    const Scene heavy = open("2hkb.pdb", "pdb", {.drop_hydrogens = true})->frame(0);
    EXPECT_LT(atom_count(heavy), atom_count(first));
    const SphereProperty& element = *property(heavy, "element");
    EXPECT_EQ(std::count(element.labels.begin(), element.labels.end(), "H"), 0);
}

TEST(MolecularFiles, AlternateLocationsKeepTheMostOccupiedUnlessAllAreAsked) {
    const std::string pdb =
        "ATOM      1  N   SER A   1       1.000   1.000   1.000  1.00 10.00           N\n"
        "ATOM      2  CA ASER A   1       2.000   2.000   2.000  0.40 10.00           C\n"
        "ATOM      3  CA BSER A   1       3.000   3.000   3.000  0.60 10.00           C\n"
        "ATOM      4  C   SER A   1       4.000   4.000   4.000  1.00 10.00           C\n";
    const Scene kept = open_molecular_bytes(pdb, "alt.pdb", "pdb", {})->frame(0);
    ASSERT_EQ(atom_count(kept), 3u);
    EXPECT_EQ(kept.spheres[1].center, (Vec3{3, 3, 3}));  // B: occupancy 0.6
    const Scene all = open_molecular_bytes(pdb, "alt.pdb", "pdb", {.all_altlocs = true})->frame(0);
    ASSERT_EQ(atom_count(all), 4u);
    EXPECT_EQ(label_of(*property(all, "altloc"), 1), "A");
}

TEST(MolecularFiles, ExtendedXyzColumnsLatticeAndFrames) {
    const auto frames = open("extended.xyz", "xyz", {.cell = true});
    ASSERT_EQ(frames->frame_count(), 3u);
    const Scene scene = frames->frame(0);
    // Lattice="8.43116035 0.0 0.0 0.158219155128 14.5042431863 0.0 1.16980663624 4.4685149855 14.9100096405"
    // Properties=species:S:1:pos:R:3:CS:R:2; the first atom: O 2.33827271799 4.55315540425 11.5841360926 24.10 31.34
    EXPECT_EQ(scene.spheres[0].center, (Vec3{2.33827271799, 4.55315540425, 11.5841360926}));
    EXPECT_EQ(label_of(*property(scene, "element"), 0), "O");
    EXPECT_FLOAT_EQ(property(scene, "CS_1")->values[0], 24.10f);
    EXPECT_FLOAT_EQ(property(scene, "CS_2")->values[0], 31.34f);
    // 192 atoms, the cell's spheres (its 8 corners among them, the corner c = the third lattice vector), two lights.
    const auto cell = std::find_if(scene.spheres.begin(), scene.spheres.end(),
                                   [](const Sphere& s) { return s.center == Vec3{1.16980663624, 4.4685149855, 14.9100096405}; });
    EXPECT_NE(cell, scene.spheres.end());
    EXPECT_GT(scene.spheres.size(), 192u + 8u + 2u);
    EXPECT_EQ(scene.materials[1].name, "cell");
    // Without --cell the atoms are all.
    EXPECT_EQ(atom_count(open("extended.xyz", "xyz")->frame(0)), 192u);
}

// The cell and the lights are not atoms: they carry no value of any property,
// so colouring by one leaves the cell grey, and the written scene says null.
TEST(MolecularFiles, TheCellAndTheLightsHaveNoPropertyValuesAndStayGreyUnderColourBy) {
    for (const auto& [file, format, by] : {std::tuple{"extended.xyz", "xyz", "CS_1"},
                                          std::tuple{"polymer-10-frames.lammpstrj", "lammps-dump", "mol"},
                                          std::tuple{"ubiquitin.gro", "gro", "element"}}) {
        Scene scene = open(file, format, {.cell = true})->frame(0);
        const std::size_t atoms = static_cast<std::size_t>(std::count_if(
            scene.spheres.begin(), scene.spheres.end(), [&](const Sphere& s) { return scene.materials[s.material].name == "atom"; }));
        ASSERT_GT(scene.spheres.size(), atoms + 2) << file << ": the cell's spheres and two lights follow the atoms";
        ASSERT_EQ(scene.materials[scene.spheres[atoms].material].name, "cell") << file;
        ASSERT_FALSE(scene.sphere_attributes.properties.empty()) << file;
        for (const SphereProperty& p : scene.sphere_attributes.properties)
            for (std::size_t i = 0; i < scene.spheres.size(); ++i)
                EXPECT_EQ(has_value(p.values[i]), i < atoms) << file << " " << p.name << " sphere " << i;
        const float grey = scene.sphere_attributes.colors[3 * atoms];
        SphereStyleOptions colour_by;
        colour_by.color_by = by;
        apply_sphere_styling(scene, colour_by, file);
        for (std::size_t i = atoms; i < scene.spheres.size(); ++i) {
            if (scene.materials[scene.spheres[i].material].name != "cell") continue;
            for (int c = 0; c < 3; ++c) EXPECT_EQ(scene.sphere_attributes.colors[3 * i + c], grey) << file << " sphere " << i;
        }
        // null in the JSON form, and back; the binary form and the hash agree.
        const std::string text = write_scene_json(scene);
        EXPECT_NE(text.find("null"), std::string::npos) << file;
        const Scene read = load_scene_json(text, file);
        EXPECT_EQ(scene_content_hash(read), scene_content_hash(scene)) << file;
        EXPECT_FALSE(has_value(read.sphere_attributes.properties.front().values.back())) << file;
        EXPECT_EQ(scene_content_hash(load_scene_binary(write_scene_binary(scene), file)), scene_content_hash(scene)) << file;
    }
}

TEST(MolecularFiles, PlainXyzTrajectory) {
    const auto frames = open("trajectory.xyz", "xyz");
    ASSERT_EQ(frames->frame_count(), 2u);
    EXPECT_EQ(frames->frame(0).camera, frames->frame(1).camera);
    const Scene methane = open("methane.xyz", "xyz")->frame(0);
    EXPECT_EQ(atom_count(methane), 5u);
}

TEST(MolecularFiles, LammpsScaledPositionsAndColumns) {
    const auto frames = open("nacl.lammpstrj", "lammps-dump");
    ASSERT_EQ(frames->frame_count(), 6u);
    const Scene scene = frames->frame(0);
    ASSERT_EQ(atom_count(scene), 512u);
    // BOX BOUNDS -1.41005 21.150751 on each axis; the first atom xs ys zs = 0.0625 0.0625 0.0625.
    const double x = -1.41005 + 0.0625 * (21.150751 + 1.41005);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(scene.spheres[0].center[c], x, 1e-12);
    EXPECT_FLOAT_EQ(property(scene, "vx")->values[0], -0.00258494f);
    EXPECT_EQ(property(scene, "element"), nullptr);  // a dump names types, not elements
}

TEST(MolecularFiles, LammpsTypesAreCategoriesAndColours) {
    const auto frames = open("polymer-10-frames.lammpstrj", "lammps-dump", {.cell = true});
    ASSERT_EQ(frames->frame_count(), 10u);
    const Scene scene = frames->frame(4);
    const SphereProperty& type = *property(scene, "type");
    EXPECT_TRUE(type.categorical());
    EXPECT_NE(property(scene, "mol"), nullptr);
    EXPECT_EQ(frames->frame(0).camera, scene.camera);
}

TEST(MolecularFiles, GroNanometresBecomeAngstromAndTheBoxACell) {
    const auto frames = open("ubiquitin.gro", "gro");
    ASSERT_EQ(frames->frame_count(), 1u);
    const Scene scene = frames->frame(0);
    ASSERT_EQ(atom_count(scene), 1405u);
    // "    1MET      N    1   2.493   2.495   1.887"
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(scene.spheres[0].center[c], (Vec3{24.93, 24.95, 18.87})[c], 1e-12);
    EXPECT_EQ(label_of(*property(scene, "element"), 0), "N");
    EXPECT_EQ(label_of(*property(scene, "residue_name"), 0), "MET");
    EXPECT_EQ(label_of(*property(scene, "atom_name"), 1), "H1");
    EXPECT_EQ(label_of(*property(scene, "element"), 1), "H");
}

}  // namespace
}  // namespace orb
