// orb-frames: expands a frame list (and a frame pattern) for shell loops and
// job scripts, and with --missing names the frames still to render.
#include <charconv>
#include <iostream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>

#include "frame_checks.h"
#include "orb/cli/frame_spec.h"
#include "orb/cli/messages.h"
#include "orb/cli/tool_main.h"

using orb::cli::UsageError;

namespace {

struct Settings {
    std::string list;
    std::string pattern;
    bool paths = false;
    bool missing = false;
    orb::frames::FrameRequirements wanted;
};

// "-" reads the list from stdin, where newlines and spaces separate items as
// commas do, so the output of one orb-frames can feed another.
std::string list_text(const std::string& list) {
    if (list != "-") return list;
    std::string text{std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
    std::string joined;
    bool pending_separator = false;
    for (char c : text) {
        if (c == '\n' || c == ' ' || c == '\t' || c == '\r' || c == ',') {
            pending_separator = !joined.empty();
            continue;
        }
        if (pending_separator) joined += ',';
        pending_separator = false;
        joined += c;
    }
    if (joined.empty()) throw UsageError("no frames on stdin");
    return joined;
}

// "START:COUNT" as orb-render writes it in orb:sampleRanges (no leading zeros).
std::string canonical_sample_range(const std::string& text) {
    const auto colon = text.find(':');
    unsigned long long start = 0, count = 0;
    const auto number = [](std::string_view part, unsigned long long& value) {
        const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
        return !part.empty() && ec == std::errc() && end == part.data() + part.size();
    };
    if (colon == std::string::npos || !number(std::string_view(text).substr(0, colon), start) ||
        !number(std::string_view(text).substr(colon + 1), count) || count < 1)
        throw UsageError("--samples: expected START:COUNT with whole numbers and COUNT >= 1, got '" + text + "'");
    return std::to_string(start) + ":" + std::to_string(count);
}

}  // namespace

int main(int argc, char** argv) {
    Settings s;
    std::optional<unsigned long long> spp;
    std::optional<int> width, height;
    std::optional<std::string> samples;
    return orb::cli::run_tool(
        argc, argv, "orb-frames", "List the frames of a frame list, their file names, or those not yet rendered",
        [&](CLI::App& app) {
            app.add_option("list", s.list, "Frames: 1-240, 1-240x10, 1,5,9-12; '-' reads them from stdin")
                ->option_text("LIST")
                ->required();
            app.add_option("pattern", s.pattern, "File name with a frame number: beauty.%04d.exr or beauty.####.exr")
                ->option_text("PATTERN");
            app.add_flag("--paths", s.paths, "Print each frame's file name instead of its number");
            app.add_flag("--missing", s.missing,
                         "Only frames whose file is not a complete orb-render EXR (reached its target spp, not truncated)");
            app.add_option("--spp", spp, "With --missing: a frame must also have exactly N samples per pixel")
                ->option_text("N")
                ->check(CLI::Range(1ULL, 2147483647ULL));
            app.add_option("--samples", samples,
                           "With --missing: a frame must also hold exactly the samples START ... START+COUNT-1 "
                           "(a slice from orb-render --sample-range)")
                ->option_text("START:COUNT");
            app.add_option("--width", width, "With --missing: a frame must also be W pixels wide")
                ->option_text("W")
                ->check(CLI::Range(1, 1 << 20));
            app.add_option("--height", height, "With --missing: a frame must also be H pixels high")
                ->option_text("H")
                ->check(CLI::Range(1, 1 << 20));
            app.footer(
                "Prints one frame number (or with --paths one file name) per line, in the list's order.\n"
                "Examples:\n"
                "  for f in $(orb-frames 1-240x2); do orb-render shot.json --frame $f -o beauty.%04d.exr; done\n"
                "  orb-frames 1-240 shots/beauty.%04d.exr --missing           # frames still to render\n"
                "  orb-frames 1-240 shots/beauty.####.exr --missing --spp 256 --paths\n"
                "Frame lists and patterns: docs/frames.md.\n"
                "Exit status: 0 success (whether or not frames are missing), 1 output failed, 2 usage error.");
        },
        [&]() -> int {
            if (samples) samples = canonical_sample_range(*samples);
            s.wanted = {spp, samples, width, height};
            if ((s.paths || s.missing) && s.pattern.empty())
                throw UsageError(std::string(s.missing ? "--missing" : "--paths") + " needs a PATTERN, e.g. beauty.%04d.exr");
            if ((spp || samples || width || height) && !s.missing)
                throw UsageError("--spp, --samples, --width and --height go with --missing");
            if (!s.pattern.empty() && orb::cli::count_frame_fields(s.pattern) == 0)
                throw UsageError("'" + s.pattern + "' has no frame number: write %04d or #### where it goes");
            const orb::cli::FrameSpec spec = orb::cli::parse_frame_spec(list_text(s.list));
            std::string out;
            for (int frame : spec) {
                const std::string path = s.pattern.empty() ? "" : orb::cli::expand_frame_pattern(s.pattern, frame);
                if (s.missing) {
                    const std::string why = orb::frames::why_not_done(path, s.wanted);
                    if (why.empty()) continue;
                    // An absent file is the usual case and says nothing new; a present one that does
                    // not count (interrupted, truncated, another --spp) is worth a note.
                    if (why != "no such file") orb::cli::info("frame " + std::to_string(frame) + ": " + path + ": " + why);
                }
                out += s.paths ? path : std::to_string(frame);
                out += '\n';
            }
            std::cout << out << std::flush;
            if (!std::cout) {
                orb::cli::error("cannot write to stdout");
                return orb::cli::kFailure;
            }
            return orb::cli::kSuccess;
        });
}
