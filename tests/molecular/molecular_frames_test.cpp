// Trajectories: frames found by offset, read from the file or from memory
// alike, particles coming and going, one camera; the radius options.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "molecular_test_util.h"
#include "orb/import/sphere_styling.h"
#include "orb/import/elements.h"
#include "orb/scene/error.h"

namespace orb {
namespace {

using test::atom_count;
using test::label_of;
using test::property;

// An XYZ trajectory whose atom count changes: 3 atoms, then 2, then 4.
const std::string kChanging =
    "3\nframe 1\nC 0 0 0\nO 1.2 0 0\nH -1 0 0\n"
    "2\nframe 2\nC 0 0.5 0\nO 1.2 0.5 0\n"
    "4\nframe 3\nC 0 1 0\nO 1.2 1 0\nH -1 1 0\nN 0 1 2\n";

std::string write_temporary(const std::string& name, const std::string& text) {
    const std::string path = (std::filesystem::temp_directory_path() / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

TEST(MolecularFrames, ParticlesComeAndGoUnderTheFirstFramesCamera) {
    const auto frames = open_molecular_bytes(kChanging, "changing.xyz", "xyz", {});
    ASSERT_EQ(frames->frame_count(), 3u);
    const Scene a = frames->frame(0), b = frames->frame(1), c = frames->frame(2);
    EXPECT_EQ(atom_count(a), 3u);
    EXPECT_EQ(atom_count(b), 2u);
    EXPECT_EQ(atom_count(c), 4u);
    EXPECT_EQ(a.camera, b.camera);
    EXPECT_EQ(a.camera, c.camera);
    EXPECT_EQ(a.spheres.back(), c.spheres.back());
    EXPECT_EQ(c.spheres[3].center, (Vec3{0, 1, 2}));
    EXPECT_EQ(label_of(*property(c, "element"), 3), "N");
    EXPECT_EQ(c.sphere_attributes.colors.size(), 3 * c.spheres.size());
}

TEST(MolecularFrames, TheFileReadByOffsetEqualsTheBytesInMemory) {
    // CR LF line ends too: offsets count every byte.
    std::string crlf;
    for (char ch : kChanging) {
        if (ch == '\n') crlf += '\r';
        crlf += ch;
    }
    const std::string path = write_temporary("orb-changing-crlf.xyz", crlf);
    const auto from_file = open_molecular_file(path, "xyz", {});
    const auto from_memory = open_molecular_bytes(kChanging, "changing.xyz", "xyz", {});
    ASSERT_EQ(from_file->frame_count(), 3u);
    // Any order: frame 3 before frame 2.
    EXPECT_EQ(from_file->frame(2), from_memory->frame(2));
    EXPECT_EQ(from_file->frame(1), from_memory->frame(1));
    std::filesystem::remove(path);
}

TEST(MolecularFrames, AFramePastTheEndIsAClearError) {
    const auto frames = open_molecular_bytes(kChanging, "changing.xyz", "xyz", {});
    try {
        frames->frame(3);
        FAIL() << "expected an error";
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "changing.xyz: has 3 frames; no frame 4");
    }
}

TEST(MolecularFrames, RadiusOptions) {
    const std::string xyz = "2\n\nC 0 0 0\nO 3 0 0\n";
    const Scene vdw = open_molecular_bytes(xyz, "m.xyz", "xyz", {})->frame(0);
    EXPECT_EQ(vdw.spheres[0].radius, 1.70);
    const Scene covalent = open_molecular_bytes(xyz, "m.xyz", "xyz", {.radius = AtomRadius::Covalent})->frame(0);
    EXPECT_EQ(covalent.spheres[1].radius, 0.66);
    const Scene scaled = open_molecular_bytes(xyz, "m.xyz", "xyz", {.radius_scale = 0.5})->frame(0);
    EXPECT_EQ(scaled.spheres[0].radius, 0.85);
    const Scene fixed =
        open_molecular_bytes(xyz, "m.xyz", "xyz", {.radius = AtomRadius::Fixed, .fixed_radius = 0.3})->frame(0);
    EXPECT_EQ(fixed.spheres[1].radius, 0.3);
}

TEST(MolecularFrames, LammpsTriclinicBoxRadiusColumnAndTypes) {
    // A box tilted by xy = 1: the bounds line holds xlo_bound xhi_bound xy = 0 11 1 (LAMMPS adds the tilt to xhi).
    const std::string dump =
        "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS xy xz yz pp pp pp\n0 11 1\n0 10 0\n0 10 0\n"
        "ITEM: ATOMS id type xs ys zs radius\n1 1 0 1 0 0.5\n2 2 1 0 0 0.7\n";
    const Scene scene = open_molecular_bytes(dump, "t.lammpstrj", "lammps-dump", {})->frame(0);
    // xs ys zs = 0 1 0 -> origin + b = (xy, 10, 0) = (1, 10, 0); 1 0 0 -> a = (10, 0, 0).
    EXPECT_EQ(scene.spheres[0].center, (Vec3{1, 10, 0}));
    EXPECT_EQ(scene.spheres[1].center, (Vec3{10, 0, 0}));
    EXPECT_EQ(scene.spheres[0].radius, 0.5);
    EXPECT_EQ(scene.spheres[1].radius, 0.7);
    const SphereProperty& type = *property(scene, "type");
    EXPECT_EQ(label_of(type, 1), "2");
    // Types coloured apart; the lights carry black and no type.
    EXPECT_NE(scene.sphere_attributes.colors[0], scene.sphere_attributes.colors[3]);
    EXPECT_FALSE(has_value(type.values.back()));
    EXPECT_EQ(scene.sphere_attributes.colors.back(), 0.0f);
}

// sRGB 8-bit -> linear, as the scene holds colours.
float linear(int encoded) {
    const double v = encoded / 255.0;
    return static_cast<float>(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
}

TEST(MolecularFrames, TypeNKeepsOkabeItoColourNMinusOneInEveryFrame) {
    // Type 3 comes first in frame 1 and last in frame 2: #009E73 (the third colour) both times.
    const std::string dump =
        "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n0 10\n"
        "ITEM: ATOMS id type x y z\n1 3 1 1 1\n2 1 5 5 5\n"
        "ITEM: TIMESTEP\n1\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n0 10\n"
        "ITEM: ATOMS id type x y z\n2 1 5 5 5\n1 3 1 1 2\n";
    const auto frames = open_molecular_bytes(dump, "t.lammpstrj", "lammps-dump", {});
    const Scene first = frames->frame(0), second = frames->frame(1);
    const std::vector<float> third{linear(0x00), linear(0x9E), linear(0x73)};
    const std::vector<float> orange{linear(0xE6), linear(0x9F), linear(0x00)};  // type 1
    const auto color = [](const Scene& scene, std::size_t i) {
        return std::vector<float>(scene.sphere_attributes.colors.begin() + 3 * i, scene.sphere_attributes.colors.begin() + 3 * i + 3);
    };
    EXPECT_EQ(color(first, 0), third);
    EXPECT_EQ(color(first, 1), orange);
    EXPECT_EQ(color(second, 1), third);
    EXPECT_EQ(color(second, 0), orange);
}

TEST(MolecularFrames, TheLightsHaveNoValueSoTheyWidenNoRange) {
    const std::string dump =
        "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n0 10\n"
        "ITEM: ATOMS id x y z c_temp\n1 1 1 1 300\n2 5 5 5 350\n";
    const Scene scene = open_molecular_bytes(dump, "t.lammpstrj", "lammps-dump", {})->frame(0);
    const SphereProperty& temp = *property(scene, "c_temp");
    ASSERT_EQ(temp.values.size(), scene.spheres.size());
    EXPECT_FALSE(has_value(temp.values[2]));
    EXPECT_FALSE(has_value(temp.values[3]));
    Scene styled = scene;
    SphereStyleOptions by_temperature;
    by_temperature.color_by = "c_temp";
    const std::pair<double, double> atoms_range{300, 350};
    EXPECT_EQ(apply_sphere_styling(styled, by_temperature, "t").color_range, atoms_range);
}

}  // namespace
}  // namespace orb
