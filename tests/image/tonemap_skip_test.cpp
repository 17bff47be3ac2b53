// orb-tonemap --skip-existing keeps only current display images: whole, made
// from the file now at the input path, with the settings asked for now.
#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "test_support.h"

using namespace orb::image;
using namespace orb::image::test;
namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

namespace {

const std::string kTonemap = quote(tonemap_exe());

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Lines of `text` that say why `output` is made again.
int reasons_for(const std::string& text, const std::string& output) {
    std::istringstream in(text);
    int n = 0;
    for (std::string line; std::getline(in, line);)
        n += line.find(output) != std::string::npos && line.find("making it again") != std::string::npos;
    return n;
}

int lines_with(const std::string& text, const std::string& needle) {
    std::istringstream in(text);
    int n = 0;
    for (std::string line; std::getline(in, line);) n += line.find(needle) != std::string::npos;
    return n;
}

ino_t inode_of(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 ? st.st_ino : 0;
}

// An EXR as orb-render leaves it, as far as the source's identity goes.
void write_render(const std::string& path, const Image& image, int spp) {
    OIIO::ImageSpec spec(image.width, image.height, image.channels(), OIIO::TypeDesc::FLOAT);
    spec.channelnames.assign(image.channel_names.begin(), image.channel_names.end());
    spec.attribute("orb:spp", spp);
    spec.attribute("orb:sceneHash", "0123456789abcdef");
    auto out = OIIO::ImageOutput::create(path);
    if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data()) ||
        !out->close())
        throw std::runtime_error("cannot write " + path);
}

class TonemapSkip : public ::testing::Test {
protected:
    ScratchDir dir;
    std::string in = dir.path("f.%04d.exr");
    std::string out = dir.path("o.%04d.png");

    static std::string frame(const std::string& pattern, int f) {
        char number[16];
        std::snprintf(number, sizeof number, "%04d", f);
        std::string path = pattern;
        path.replace(path.find("%04d"), 4, number);
        return path;
    }
    // Frame f is a multi-pass render of its own brightness.
    void write_frames(int count) {
        for (int f = 1; f <= count; ++f) {
            Image image = make_multipass(16, 8);
            for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] *= static_cast<float>(f);
            write_exr(frame(in, f), image);
        }
    }
    CommandResult tonemap(const std::string& options, const std::string& frames = "1-3") {
        return run(kTonemap + " " + quote(in) + " --frames " + frames + " -o " + quote(out) + " " + options);
    }
    std::vector<std::string> outputs(int count) {
        std::vector<std::string> bytes;
        for (int f = 1; f <= count; ++f) bytes.push_back(read_bytes(frame(out, f)));
        return bytes;
    }
};

}  // namespace

TEST_F(TonemapSkip, ASequenceRunAgainIsSkippedWhole) {
    write_frames(3);
    ASSERT_EQ(tonemap("-q").exit_code, 0);
    const auto before = outputs(3);
    const auto again = tonemap("--skip-existing");
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_NE(again.err.find("skipped 3 of 3 outputs that are current"), std::string::npos) << again.err;
    EXPECT_EQ(again.err.find("making it again"), std::string::npos) << again.err;
    EXPECT_EQ(outputs(3), before);
    // Asking by name for what the defaults are (display sRGB, view Standard, 8 bits) is asking for the same images.
    const auto named = tonemap("--skip-existing --display sRGB --view Standard --bits 8 --pass beauty --exposure 0");
    EXPECT_NE(named.err.find("skipped 3 of 3"), std::string::npos) << named.err;
}

TEST_F(TonemapSkip, ARewrittenSourceRemakesOnlyItsFrame) {
    write_frames(3);
    ASSERT_EQ(tonemap("-q").exit_code, 0);
    const auto before = outputs(3);
    write_exr(frame(in, 2), make_multipass(16, 8));  // frame 2 rendered again, with other pixels
    const auto r = tonemap("--skip-existing");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto after = outputs(3);
    EXPECT_EQ(after[0], before[0]);
    EXPECT_NE(after[1], before[1]);
    EXPECT_EQ(after[2], before[2]);
    EXPECT_EQ(reasons_for(r.err, "o.0002.png"), 1) << r.err;
    EXPECT_EQ(reasons_for(r.err, "o.000"), 1) << r.err;
    EXPECT_NE(r.err.find("o.0002.png: its source " + frame(in, 2) + " changed since it was made: making it again"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("skipped 2 of 3 outputs"), std::string::npos) << r.err;
    // The image now is the one a fresh run makes.
    ASSERT_EQ(run(kTonemap + " " + quote(frame(in, 2)) + " -o " + quote(dir.path("fresh.png")) + " -q").exit_code, 0);
    EXPECT_EQ(read_image(frame(out, 2)).pixels, read_image(dir.path("fresh.png")).pixels);
}

TEST_F(TonemapSkip, ARenderAgainInTheSameClockTickIsToldByItsHeader) {
    const Image image = make_scene(16, 8, 4.0f);
    write_render(frame(in, 1), image, 64);
    ASSERT_EQ(tonemap("-q", "1").exit_code, 0);
    struct stat first {};
    ASSERT_EQ(::stat(frame(in, 1).c_str(), &first), 0);
    // The same pixels with more samples claimed: same size; the clock put back to the same nanosecond.
    write_render(frame(in, 1), image, 256);
    const timespec times[2] = {first.st_atim, first.st_mtim};
    ASSERT_EQ(::utimensat(AT_FDCWD, frame(in, 1).c_str(), times, 0), 0);
    ASSERT_EQ(fs::file_size(frame(in, 1)), static_cast<uintmax_t>(first.st_size));
    const auto r = tonemap("--skip-existing", "1");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("its source " + frame(in, 1) + " was rendered again (orb:spp 64, now 256): making it again"),
              std::string::npos)
        << r.err;
}

TEST_F(TonemapSkip, OtherSettingsRemakeEveryFrame) {
    write_frames(3);
    // Another config with the same content is the same config; one edited is another.
    const std::string same_config = dir.path("same.ocio"), edited_config = dir.path("edited.ocio");
    fs::copy_file(ocio_config(), same_config);
    fs::copy_file(ocio_config(), edited_config);
    std::ofstream(edited_config, std::ios::app) << "\n# edited\n";
    ASSERT_EQ(tonemap("-q").exit_code, 0);
    const auto same = tonemap("--skip-existing --config " + quote(same_config));
    EXPECT_NE(same.err.find("skipped 3 of 3"), std::string::npos) << same.err;

    struct Case {
        std::string options, reason;
    };
    const std::vector<Case> cases = {
        {"--exposure 1", "made with --exposure 0, 1 asked"},
        {"--exposure 1 --view Filmic", "made with --view Standard, Filmic asked"},
        {"--exposure 1 --view Filmic --display 'Display P3'", "made with --display sRGB, Display P3 asked"},
        {"--exposure 1 --view Filmic --display 'Display P3' --look 'High Contrast'",
         "made with --look (the view's own), High Contrast asked"},
        {"--exposure 1 --view Filmic --display 'Display P3' --look 'High Contrast' --input-space ACEScg",
         "made with --input-space (the input's own), ACEScg asked"},
        {"--pass albedo", "made with --pass beauty, albedo asked"},
        {"--contact-sheet", "made from --pass albedo, a contact sheet asked"},
        {"--contact-sheet --no-dither", "made dithered, --no-dither asked"},
        {"--contact-sheet --bits 16", "made with --bits 8, 16 asked"},
        {"--contact-sheet --bits 16 --config " + quote(edited_config), "made with another colour config"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.options);
        const auto before = outputs(3);
        const auto r = tonemap("--skip-existing " + c.options);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        for (int f = 1; f <= 3; ++f) {
            EXPECT_EQ(reasons_for(r.err, frame(out, f)), 1) << r.err;
            EXPECT_NE(r.err.find(frame(out, f) + ": " + c.reason), std::string::npos) << r.err;
        }
        EXPECT_EQ(r.err.find("skipped"), std::string::npos) << r.err;
        EXPECT_NE(outputs(3), before);
        // Asked again, they are current.
        const auto again = tonemap("--skip-existing " + c.options);
        EXPECT_NE(again.err.find("skipped 3 of 3"), std::string::npos) << again.err;
    }
}

TEST_F(TonemapSkip, AnOutputWithoutARecordIsMadeAgain) {
    write_frames(2);
    // Frame 1 as an older orb-tonemap (or any other program) left it; frame 2
    // with a record from an orb-tonemap that made pixels another way.
    write_png(frame(out, 1), make_scene(16, 8, 1.0f));
    {
        OIIO::ImageSpec spec(4, 4, 3, OIIO::TypeDesc::UINT8);
        spec.attribute("orb:tonemap", "orb-tonemap display image 0\n");
        auto o = OIIO::ImageOutput::create(frame(out, 2));
        const std::vector<float> grey(4 * 4 * 3, 0.5f);
        ASSERT_TRUE(o && o->open(frame(out, 2), spec) && o->write_image(OIIO::TypeDesc::FLOAT, grey.data()) &&
                    o->close());
    }
    const auto r = tonemap("--skip-existing", "1-2");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find(frame(out, 1) + ": it has no record of what it was made from (an older orb-tonemap or "
                                         "another program wrote it): making it again"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find(frame(out, 2) + ": an orb-tonemap that makes pixels differently made it (record version 0"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(read_image(frame(out, 1)).width, 16);
    EXPECT_EQ(read_image(frame(out, 2)).width, 16);
    EXPECT_NE(tonemap("--skip-existing", "1-2").err.find("skipped 2 of 2"), std::string::npos);
}

TEST_F(TonemapSkip, ADamagedOutputIsMadeAgain) {
    write_frames(2);
    ASSERT_EQ(tonemap("-q", "1-2").exit_code, 0);
    const std::string good = read_bytes(frame(out, 2));
    fs::resize_file(frame(out, 2), good.size() / 2);  // cut short after it was written
    std::ofstream(frame(out, 1)) << "not a png";
    const auto r = tonemap("--skip-existing", "1-2");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(reasons_for(r.err, frame(out, 1)), 1) << r.err;
    EXPECT_EQ(reasons_for(r.err, frame(out, 2)), 1) << r.err;
    EXPECT_NE(r.err.find("making it again"), std::string::npos) << r.err;
    EXPECT_EQ(read_bytes(frame(out, 2)), good);
    EXPECT_EQ(read_image(frame(out, 1)).width, 16);
}

TEST_F(TonemapSkip, AnOutputWhoseSourceIsGoneIsKept) {
    write_frames(2);
    ASSERT_EQ(tonemap("-q", "1-2").exit_code, 0);
    const auto before = outputs(2);
    fs::remove(frame(in, 2));
    const auto r = tonemap("--skip-existing", "1-2");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("skipped 2 of 2"), std::string::npos) << r.err;
    EXPECT_EQ(outputs(2), before);
    // Other settings cannot be had without the source: an error, and the old image stays.
    const auto other = tonemap("--skip-existing --exposure 2", "1-2");
    EXPECT_EQ(other.exit_code, 1);
    EXPECT_NE(other.err.find(frame(in, 2)), std::string::npos) << other.err;
    EXPECT_EQ(outputs(2)[1], before[1]);
}

TEST_F(TonemapSkip, StandardInputCannotBeJudgedSoItIsMade) {
    write_frames(1);
    const std::string png = dir.path("piped.png");
    const std::string command = "cat " + quote(frame(in, 1)) + " | " + kTonemap + " - --skip-existing -o " + quote(png);
    ASSERT_EQ(run(command).exit_code, 0);
    const ino_t first = inode_of(png);
    const auto r = run(command);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(lines_with(r.err, "--skip-existing"), 1) << r.err;
    EXPECT_NE(r.err.find("--skip-existing: <stdin> is not a file"), std::string::npos) << r.err;
    EXPECT_NE(inode_of(png), first) << "written again";
    // An image made from stdin is not current for a file input either.
    const auto from_file = run(kTonemap + " " + quote(frame(in, 1)) + " --skip-existing -o " + quote(png));
    EXPECT_NE(from_file.err.find("it was made from standard input or another stream, not from " + frame(in, 1)),
              std::string::npos)
        << from_file.err;
}

TEST_F(TonemapSkip, EveryFormatWithARecordIsSkippedWhenCurrent) {
    write_frames(1);
    // Makes one.EXT, then runs --skip-existing on it: the second run's
    // result, and whether the file was left in place (the same inode).
    struct Again {
        CommandResult run;
        bool left_alone;
    };
    const auto make_then_skip = [&](const std::string& o) {
        EXPECT_EQ(run(kTonemap + " " + quote(frame(in, 1)) + " -o " + quote(o) + " -q").exit_code, 0);
        const ino_t first = inode_of(o);
        CommandResult again = run(kTonemap + " " + quote(frame(in, 1)) + " --skip-existing -o " + quote(o));
        return Again{again, inode_of(o) == first};
    };
    for (const std::string ext : {"png", "jpg", "tif", "exr"}) {
        SCOPED_TRACE(ext);
        const Again r = make_then_skip(dir.path("one." + ext));
        ASSERT_EQ(r.run.exit_code, 0) << r.run.err;
        EXPECT_NE(r.run.err.find("skipped 1 of 1 output that is current"), std::string::npos) << r.run.err;
        EXPECT_TRUE(r.left_alone);
    }
    // Formats that keep no record are made every time, with a line saying why.
    for (const std::string ext : {"bmp", "ppm"}) {
        SCOPED_TRACE(ext);
        const std::string o = dir.path("one." + ext);
        const Again r = make_then_skip(o);
        ASSERT_EQ(r.run.exit_code, 0) << r.run.err;
        EXPECT_NE(r.run.err.find(o + ": " + ext + " images keep no record of what they were made from: making it again"),
                  std::string::npos)
            << r.run.err;
        EXPECT_FALSE(r.left_alone);
    }
    // --format changes what the image is, whatever its name says.
    const std::string named_png = dir.path("one.png");
    const auto as_jpeg =
        run(kTonemap + " " + quote(frame(in, 1)) + " --skip-existing --format jpg -o " + quote(named_png));
    EXPECT_NE(as_jpeg.err.find("made as png, jpg asked"), std::string::npos) << as_jpeg.err;
}

// --missing lists what --skip-existing would make, by the same rule, and makes nothing.
TEST_F(TonemapSkip, MissingListsWhatSkipExistingWouldMake) {
    write_frames(4);
    ASSERT_EQ(tonemap("-q", "1-3").exit_code, 0);  // frame 4 has no output
    write_exr(frame(in, 2), make_multipass(16, 8));  // frame 2 rendered again
    std::ofstream(frame(out, 3)) << "not a png";    // frame 3's output damaged
    const auto before = outputs(3);
    const auto r = tonemap("--missing", "1-4");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "2\n3\n4\n");
    EXPECT_NE(r.err.find("frame 2: " + frame(out, 2) + ": its source " + frame(in, 2) + " changed since it was made"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("frame 3: " + frame(out, 3) + ": does not read whole"), std::string::npos) << r.err;
    EXPECT_EQ(lines_with(r.err, "frame 4"), 0) << r.err;  // absent: nothing to say
    EXPECT_EQ(lines_with(r.err, "making it again"), 0) << r.err;
    EXPECT_EQ(outputs(3), before);
    EXPECT_FALSE(fs::exists(frame(out, 4)));
    // -q keeps the list and drops the reasons; other settings make every output stale.
    const auto quiet = tonemap("--missing -q --exposure 1", "1-4");
    EXPECT_EQ(quiet.exit_code, 0);
    EXPECT_EQ(quiet.out, "1\n2\n3\n4\n");
    EXPECT_EQ(quiet.err, "");
    // After --skip-existing has made them, nothing is missing.
    ASSERT_EQ(tonemap("--skip-existing -q", "1-4").exit_code, 0);
    const auto after = tonemap("--missing", "1-4");
    EXPECT_EQ(after.exit_code, 0);
    EXPECT_EQ(after.out, "");
    EXPECT_EQ(after.err, "");
    // Without --frames it names the output; -o - cannot be judged.
    const std::string single = dir.path("single.png");
    const auto one = run(kTonemap + " " + quote(frame(in, 1)) + " --missing -o " + quote(single));
    EXPECT_EQ(one.exit_code, 0) << one.err;
    EXPECT_EQ(one.out, single + "\n");
    EXPECT_FALSE(fs::exists(single));
    const auto to_stdout = run(kTonemap + " " + quote(frame(in, 1)) + " --missing --format png -o -");
    EXPECT_EQ(to_stdout.exit_code, 2);
    EXPECT_NE(to_stdout.err.find("--missing needs an output file, not -o -"), std::string::npos) << to_stdout.err;
}
