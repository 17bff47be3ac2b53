// The record orb-tonemap keeps in a display image: its text form and how two
// sets of settings are told apart.
#include <gtest/gtest.h>

#include "orb/image/display_record.h"
#include "orb/image/display_settings.h"

using namespace orb::image;

namespace {

DisplayRecord sample_record() {
    DisplayRecord r;
    r.source_is_file = true;
    r.source.size = 1048576;
    r.source.mtime_ns = 1718000000123456789;
    r.source.render = {{"orb:sceneHash", "0123456789abcdef"}, {"orb:spp", "256"}};
    DisplaySettings& s = r.settings;
    s.pass = "beauty";
    s.input_space = "";
    s.display = "sRGB";
    s.view = "Filmic";
    s.look = "a look, with\nodd \\ characters";
    s.exposure = 0.1;
    s.config = "00ff00ff00ff00ff";
    s.format = "png";
    s.bits = 8;
    s.dither = true;
    s.auto_exposure = true;
    s.alpha = "over 0.18,0.5,1e-05";
    return r;
}

}  // namespace

TEST(DisplayRecord, RoundTripsEveryField) {
    const DisplayRecord r = sample_record();
    const std::string text = format_display_record(r);
    EXPECT_EQ(text.rfind("orb-tonemap display image 2\n", 0), 0u) << text;
    EXPECT_NE(text.find("\nexposure=0.1\n"), std::string::npos) << "exposure as typed: " << text;
    const auto back = parse_display_record(text);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->version, r.version);
    EXPECT_TRUE(back->source_is_file);
    EXPECT_EQ(back->source, r.source);
    EXPECT_EQ(back->settings, r.settings);
}

TEST(DisplayRecord, AStreamSourceHasNoIdentity) {
    DisplayRecord r = sample_record();
    r.source_is_file = false;
    r.settings.contact_sheet = true;
    r.settings.pass = "";
    const auto back = parse_display_record(format_display_record(r));
    ASSERT_TRUE(back);
    EXPECT_FALSE(back->source_is_file);
    EXPECT_EQ(back->settings, r.settings);
}

TEST(DisplayRecord, ExposuresCompareExactly) {
    for (double stops : {0.0, -0.0, 1.0, 0.1, 1.0 / 3.0, -100.0, 99.99999999999999}) {
        DisplayRecord r = sample_record();
        r.settings.exposure = stops;
        const auto back = parse_display_record(format_display_record(r));
        ASSERT_TRUE(back);
        EXPECT_EQ(back->settings.exposure, stops);
    }
}

TEST(DisplayRecord, WhatIsNotARecordDoesNotParse) {
    const std::string good = format_display_record(sample_record());
    EXPECT_FALSE(parse_display_record(""));
    EXPECT_FALSE(parse_display_record("A photo of a cat"));
    EXPECT_FALSE(parse_display_record("orb-tonemap display image x\n"));
    // A field missing, a value malformed, an unknown escape.
    std::string missing = good;
    missing.erase(missing.find("view="), missing.find('\n', missing.find("view=")) - missing.find("view=") + 1);
    EXPECT_FALSE(parse_display_record(missing));
    std::string bad_bits = good;
    bad_bits.replace(bad_bits.find("bits=8"), 6, "bits=eight");
    EXPECT_FALSE(parse_display_record(bad_bits));
    std::string bad_escape = good;
    bad_escape.replace(bad_escape.find("pass=beauty"), 11, "pass=be\\auty");
    EXPECT_FALSE(parse_display_record(bad_escape));
}

TEST(DisplayRecord, AnotherVersionParsesAsFarAsItsVersion) {
    const auto other = parse_display_record("orb-tonemap display image 7\nwhatever=comes next\n");
    ASSERT_TRUE(other);
    EXPECT_EQ(other->version, 7);
}

TEST(DisplaySettings, DifferencesAreNamedAsOnTheCommandLine) {
    const DisplaySettings made = sample_record().settings;
    EXPECT_TRUE(settings_differences(made, made).empty());

    DisplaySettings asked = made;
    asked.exposure = 1;
    asked.view = "Standard";
    const auto both = settings_differences(made, asked);
    ASSERT_EQ(both.size(), 2u);
    EXPECT_EQ(both[0], "made with --view Filmic, Standard asked");
    EXPECT_EQ(both[1], "made with --exposure 0.1, 1 asked");

    asked = made;
    asked.contact_sheet = true;
    asked.pass = "";
    EXPECT_EQ(settings_differences(made, asked).at(0), "made from --pass beauty, a contact sheet asked");
    asked = made;
    asked.pass = "normal";
    EXPECT_EQ(settings_differences(made, asked).at(0), "made with --pass beauty, normal asked");
    asked = made;
    asked.config = "ffffffffffffffff";
    EXPECT_EQ(settings_differences(made, asked).at(0), "made with another colour config (its content differs)");
    asked = made;
    asked.format = "jpg";
    EXPECT_EQ(settings_differences(made, asked).at(0), "made as png, jpg asked");
    asked = made;
    asked.bits = 16;
    asked.dither = false;  // never at 16 bits: the bits say it all
    EXPECT_EQ(settings_differences(made, asked), std::vector<std::string>{"made with --bits 8, 16 asked"});
    asked = made;
    asked.dither = false;
    EXPECT_EQ(settings_differences(made, asked), std::vector<std::string>{"made dithered, --no-dither asked"});
    asked = made;
    asked.input_space = "ACEScg";
    asked.look = "";
    const auto spaces = settings_differences(made, asked);
    ASSERT_EQ(spaces.size(), 2u);
    EXPECT_EQ(spaces[0], "made with --input-space (the input's own), ACEScg asked");
    EXPECT_EQ(spaces[1].rfind("made with --look a look", 0), 0u) << spaces[1];
}
