#include "orb/image/display_settings.h"

#include "number_text.h"

namespace orb::image {
namespace {

std::string shown(const std::string& value, const char* when_empty) { return value.empty() ? when_empty : value; }

std::string bits_name(int bits, const std::string& format) {
    if (format == "exr") return bits == 32 ? "32 (float)" : "16 (half)";
    return std::to_string(bits);
}

}  // namespace

std::vector<std::string> settings_differences(const DisplaySettings& made, const DisplaySettings& asked) {
    std::vector<std::string> out;
    auto differ = [&out](const std::string& option, const std::string& was, const std::string& now) {
        if (was != now) out.push_back("made with " + option + " " + was + ", " + now + " asked");
    };
    if (made.contact_sheet != asked.contact_sheet)
        out.push_back(made.contact_sheet ? "made as a contact sheet, --pass " + asked.pass + " asked"
                                         : "made from --pass " + made.pass + ", a contact sheet asked");
    else
        differ("--pass", made.pass, asked.pass);
    differ("--input-space", shown(made.input_space, "(the input's own)"),
           shown(asked.input_space, "(the input's own)"));
    differ("--display", made.display, asked.display);
    differ("--view", made.view, asked.view);
    differ("--look", shown(made.look, "(the view's own)"), shown(asked.look, "(the view's own)"));
    if (made.exposure != asked.exposure)
        differ("--exposure", shortest_text(made.exposure), shortest_text(asked.exposure));
    if (made.auto_exposure != asked.auto_exposure)
        out.push_back(made.auto_exposure ? "made with --auto-exposure, a fixed exposure asked"
                                         : "made with a fixed exposure, --auto-exposure asked");
    if (made.alpha != asked.alpha) out.push_back("made " + made.alpha + ", " + asked.alpha + " asked");
    if (made.config != asked.config) out.push_back("made with another colour config (its content differs)");
    // Bits follow from the format, and dithering from the bits: only the first of them that differs is named.
    if (made.format != asked.format)
        out.push_back("made as " + made.format + ", " + asked.format + " asked");
    else if (made.bits != asked.bits)
        differ("--bits", bits_name(made.bits, made.format), bits_name(asked.bits, asked.format));
    else if (made.dither != asked.dither)
        out.push_back(made.dither ? "made dithered, --no-dither asked" : "made with --no-dither, dithering asked");
    return out;
}

}  // namespace orb::image
