// A numbered series of files ("dump.*.lammpstrj") read as one trajectory:
// the files in the order of their numbers, each file's frames one after
// another, frame 1's camera for all; every way a series can be wrong is one
// error naming the file. And frame 1, read to place the camera, is handed
// out rather than read again.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "molecular_test_util.h"
#include "orb/scene/error.h"
#include "orb/import/import.h"
#include "orb/import/molecular.h"
#include "orb/import/numbered_series.h"

namespace orb {
namespace {

namespace fs = std::filesystem;

class NumberedSeries : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() /
                  ("orb-series-" + std::to_string(::getpid()) + "-" +
                   ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    std::string path(const std::string& name) const { return (folder_ / name).string(); }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(path(name), std::ios::binary) << text;
        return path(name);
    }
    // One water molecule lifted by `y`.
    std::string water(double y) const {
        return "3\nlifted " + std::to_string(y) + "\nO 0 " + std::to_string(y) + " 0\nH 0.76 " +
               std::to_string(y + 0.59) + " 0\nH -0.76 " + std::to_string(y + 0.59) + " 0\n";
    }
    // The message of the InputError `open` throws.
    template <typename F>
    std::string error_of(F open) const {
        try {
            open();
        } catch (const InputError& e) {
            return e.what();
        }
        return "(no error)";
    }

    fs::path folder_;
};

TEST_F(NumberedSeries, FilesAreOrderedByTheirNumberNotTheirName) {
    for (int n = 100; n >= 0; n -= 10) write("frame." + std::to_string(n) + ".xyz", water(n));
    write("frame.10.xyz.bak", water(0));  // another name: not part of it
    const std::vector<SeriesFile> files = find_numbered_series(path("frame.*.xyz"));
    ASSERT_EQ(files.size(), 11u);
    for (std::size_t k = 0; k < files.size(); ++k) {
        EXPECT_EQ(files[k].number, 10 * k);
        EXPECT_EQ(files[k].path, path("frame." + std::to_string(10 * k) + ".xyz"));
    }
}

TEST_F(NumberedSeries, AGapIsAnErrorNamingTheMissingFile) {
    for (int n : {0, 9, 10}) write("frame." + std::to_string(n) + ".xyz", water(n));
    // 9 to 10 steps by 1, so frame.1.xyz is missing.
    EXPECT_EQ(error_of([&] { open_molecular_series(path("frame.*.xyz"), {}); }),
              path("frame.*.xyz") + ": " + path("frame.1.xyz") + " is missing: the series steps by 1, and " +
                  path("frame.0.xyz") + " is followed by " + path("frame.9.xyz"));
    // Steps that are no multiple of the smallest.
    fs::remove(path("frame.9.xyz"));
    write("frame.25.xyz", water(25));
    EXPECT_EQ(error_of([&] { find_numbered_series(path("frame.*.xyz")); }),
              path("frame.*.xyz") + ": the numbers do not step evenly: " + path("frame.10.xyz") + " is followed by " +
                  path("frame.25.xyz") + ", 15 on, where the smallest step is 10");
}

TEST_F(NumberedSeries, ItsFramesAreTheFilesFramesOneAfterAnotherUnderOneCamera) {
    // Timesteps 0, 50, 100; the middle file holds two frames.
    write("md.0.xyz", water(0));
    write("md.50.xyz", water(1) + water(2));
    write("md.100.xyz", water(3));
    const auto series = open_molecular_series(path("md.*.xyz"), {});
    ASSERT_EQ(series->frame_count(), 4u);
    EXPECT_EQ(series->format(), "xyz");
    const std::string all = water(0) + water(1) + water(2) + water(3);
    const auto alone = open_molecular_bytes(all, "all.xyz", "xyz", {});
    for (std::size_t k = 0; k < 4; ++k) {
        const Scene frame = series->frame(k);
        EXPECT_EQ(frame.spheres, alone->frame(k).spheres) << k;
        EXPECT_EQ(frame.camera, alone->frame(0).camera) << k;
        EXPECT_DOUBLE_EQ(frame.spheres[0].center[1], static_cast<double>(k)) << k;
    }
}

// Real files: chemfiles' polymer dump, its 10 timesteps (0, 500, ..., 4500) cut into a file each.
TEST_F(NumberedSeries, ADumpCutIntoAFilePerTimestepIsTheSameTrajectory) {
    const std::string text = test::read_data("polymer-10-frames.lammpstrj");
    const std::string marker = "ITEM: TIMESTEP\n";
    std::size_t start = 0;
    int files = 0;
    while (start < text.size()) {
        std::size_t next = text.find(marker, start + marker.size());
        if (next == std::string::npos) next = text.size();
        const std::string frame = text.substr(start, next - start);
        const std::string timestep = frame.substr(marker.size(), frame.find('\n', marker.size()) - marker.size());
        write("dump." + timestep + ".lammpstrj", frame);
        ++files;
        start = next;
    }
    ASSERT_EQ(files, 10);
    const auto series = open_molecular_series(path("dump.*.lammpstrj"), {});
    const auto whole = open_molecular_file(test::data_path("polymer-10-frames.lammpstrj"), "lammps-dump", {});
    ASSERT_EQ(series->frame_count(), 10u);
    for (std::size_t k : {0u, 1u, 9u}) EXPECT_EQ(series->frame(k), whole->frame(k)) << k;
    // orb-import's frame of it, as of the one file.
    ImportOptions options;
    options.of<MolecularImportOptions>().frame = 10;
    const ImportResult imported = import_molecular_series(path("dump.*.lammpstrj"), options);
    EXPECT_EQ(imported.format, "lammps-dump");
    EXPECT_EQ(imported.scene, whole->frame(9));
    // --from names the series' format, by its name or an alias, or it is an error.
    options.format = "lammpstrj";
    EXPECT_EQ(import_molecular_series(path("dump.*.lammpstrj"), options).scene, whole->frame(9));
    options.format = "xyz";
    EXPECT_EQ(error_of([&] { import_molecular_series(path("dump.*.lammpstrj"), options); }),
              path("dump.*.lammpstrj") + ": --from xyz, but the series is lammps-dump");
}

TEST_F(NumberedSeries, ZeroPaddedNumbersAndAMissingFileNamedAsTheSeriesNamesThem) {
    for (int n : {1, 2, 4}) write("f." + std::string(n < 10 ? "000" : "00") + std::to_string(n) + ".xyz", water(n));
    EXPECT_EQ(error_of([&] { find_numbered_series(path("f.*.xyz")); }),
              path("f.*.xyz") + ": " + path("f.0003.xyz") + " is missing: the series steps by 1, and " +
                  path("f.0002.xyz") + " is followed by " + path("f.0004.xyz"));
}

TEST_F(NumberedSeries, EveryWayAPatternCanBeWrongIsOneError) {
    const std::string pattern = path("frame.*.xyz");
    EXPECT_EQ(error_of([&] { find_numbered_series(pattern); }),
              pattern + ": no file matches (a numbered series: frame.0.xyz, frame.1.xyz, ... in " + folder_.string() +
                  "/)");
    write("frame.1.xyz", water(1));
    write("frame.01.xyz", water(1));
    EXPECT_EQ(error_of([&] { find_numbered_series(pattern); }),
              pattern + ": " + path("frame.01.xyz") + " and " + path("frame.1.xyz") +
                  " have the same number; keep one of them");
    fs::remove(path("frame.01.xyz"));
    write("frame.last.xyz", water(1));
    EXPECT_EQ(error_of([&] { find_numbered_series(pattern); }),
              pattern + ": " + path("frame.last.xyz") +
                  " matches the pattern but has no number where the * is ('last'); move it away, or name the "
                  "series more closely");
    fs::remove(path("frame.last.xyz"));
    write("frame.12345678901234567890.xyz", water(1));
    EXPECT_NE(error_of([&] { find_numbered_series(pattern); }).find("the number is too long to read"), std::string::npos);
    fs::remove(path("frame.12345678901234567890.xyz"));
    EXPECT_NE(error_of([&] { find_numbered_series(path("*.*.xyz")); }).find("has one * where the frame number is"),
              std::string::npos);
    EXPECT_NE(error_of([&] { find_numbered_series(folder_.string() + "/*/frame.1.xyz"); })
                  .find("the folder cannot have one"),
              std::string::npos);
    EXPECT_TRUE(is_series_pattern(pattern));
    EXPECT_FALSE(is_series_pattern(path("frame.1.xyz")));
}

TEST_F(NumberedSeries, MixedFormatsAndStructureSeriesAreRefused) {
    write("s.1.dat", water(0));
    write("s.2.dat", test::read_data("nacl.lammpstrj"));
    EXPECT_EQ(error_of([&] { open_molecular_series(path("s.*.dat"), {}); }),
              path("s.*.dat") + ": mixed formats: " + path("s.1.dat") + " is xyz, " + path("s.2.dat") +
                  " is lammps-dump; a series is of one format");
    write("m.1.pdb", test::read_data("4hhb.pdb"));
    EXPECT_NE(error_of([&] { open_molecular_series(path("m.*.pdb"), {}); })
                  .find("a numbered series of pdb files is not read"),
              std::string::npos);
    // A malformed file of the series is named with its line.
    write("t.1.xyz", water(0));
    write("t.2.xyz", "3\ncut short\nO 0 0 0\n");
    EXPECT_NE(error_of([&] { open_molecular_series(path("t.*.xyz"), {}); }).find(path("t.2.xyz") + ":"),
              std::string::npos);
}

// Frame 1 is built once to place the camera; the first to ask for it gets that scene.
TEST(FrameOne, IsBuiltOnceAndHandedOutAsReadAgain) {
    const std::string path = test::data_path("trajectory.xyz");
    const auto frames = open_molecular_file(path, "xyz", {});
    EXPECT_EQ(frames->frames_built(), 1u);
    const Scene first = frames->frame(0);
    EXPECT_EQ(frames->frames_built(), 1u);
    const Scene again = frames->frame(0);  // asked for again: read anew, the same scene
    EXPECT_EQ(frames->frames_built(), 2u);
    EXPECT_EQ(first, again);
    frames->frame(1);
    EXPECT_EQ(frames->frames_built(), 3u);
}

}  // namespace
}  // namespace orb
