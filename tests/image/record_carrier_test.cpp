// Each output format orb-tonemap keeps a record in gives it back byte for
// byte; the formats it keeps none in really lose it.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <fstream>

#include "orb/image/display_record.h"
#include "orb/image/record_carrier.h"
#include "orb/image/write.h"
#include "orb/scene/error.h"
#include "test_support.h"

using namespace orb::image;
using namespace orb::image::test;
namespace OIIO = OIIO_NAMESPACE;

namespace {

// A record as long as real ones get, with every character class a value may hold.
std::string sample_record_text() {
    DisplayRecord r;
    r.source_is_file = true;
    r.source.size = 123456789;
    r.source.mtime_ns = 1718000000123456789;
    r.source.render = {
        {"orb:sceneHash", "0123456789abcdef"}, {"orb:sampleRanges", "0-255,512-767"}, {"orb:spp", "512"}};
    r.settings.pass = "beauty";
    r.settings.display = "sRGB";
    r.settings.view = "ACES 1.0 - SDR Video";
    r.settings.look = "Look: \"odd\" \\ one; 100%";
    r.settings.exposure = -1.0 / 3.0;
    r.settings.config = "fedcba9876543210";
    r.settings.format = "png";
    r.settings.bits = 8;
    r.settings.dither = true;
    return format_display_record(r);
}

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

class RecordCarrier : public ::testing::Test {
protected:
    ScratchDir dir;
    Image picture = Image(12, 7, {"R", "G", "B"}, 0.25f);
};

}  // namespace

TEST_F(RecordCarrier, EachSupportedFormatKeepsTheRecordExactly) {
    const std::string record = sample_record_text();
    struct Case {
        std::string format;
        int bits;
    };
    for (const Case& c : {Case{"png", 8}, Case{"png", 16}, Case{"jpg", 8}, Case{"tif", 8}, Case{"tif", 16},
                          Case{"exr", 16}, Case{"exr", 32}}) {
        SCOPED_TRACE(c.format + " " + std::to_string(c.bits));
        ASSERT_FALSE(record_attribute_for(c.format).empty());
        WriteOptions options;
        options.format = c.format;
        options.bits = c.bits;
        options.record = record;
        const std::string path = dir.path("image." + c.format);
        write_bytes(path, encode_image(picture, checked_write_options(options)));
        EXPECT_EQ(read_record_text(path), record);
        EXPECT_EQ(read_image(path).width, 12);
    }
}

TEST_F(RecordCarrier, FormatsWithoutACarrierLoseWhatTheyAreGiven) {
    // Written here straight through OpenImageIO with both candidate attributes,
    // to show that these formats keep neither: orb-tonemap makes them again every time.
    for (const std::string format : {"bmp", "hdr", "ppm"}) {
        SCOPED_TRACE(format);
        EXPECT_TRUE(record_attribute_for(format).empty());
        const std::string path = dir.path("image." + format);
        OIIO::ImageSpec spec(picture.width, picture.height, 3,
                             format == "hdr" ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
        spec.attribute("orb:tonemap", sample_record_text());
        spec.attribute("ImageDescription", sample_record_text());
        auto out = OIIO::ImageOutput::create(path);
        ASSERT_TRUE(out && out->open(path, spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, picture.pixels.data()) && out->close());
        EXPECT_EQ(read_record_text(path), "");
    }
}

TEST_F(RecordCarrier, ADescriptionThatIsNotARecordIsNoRecord) {
    for (const std::string format : {"tif", "jpg", "png"}) {
        SCOPED_TRACE(format);
        const std::string path = dir.path("photo." + format);
        OIIO::ImageSpec spec(picture.width, picture.height, 3, OIIO::TypeDesc::UINT8);
        spec.attribute("ImageDescription", "A photo of the Cornell box");
        auto out = OIIO::ImageOutput::create(path);
        ASSERT_TRUE(out && out->open(path, spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, picture.pixels.data()) && out->close());
        EXPECT_EQ(read_record_text(path), "");
    }
}

TEST_F(RecordCarrier, AFileThatIsNoImageIsAnError) {
    write_bytes(dir.path("junk.png"), "not a png");
    EXPECT_THROW(read_record_text(dir.path("junk.png")), orb::InputError);
}
