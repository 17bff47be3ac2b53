// orb-frames: expands a frame list (and a frame pattern) for shell loops and
// job scripts, and with --missing names the frames still to render.
#include <charconv>
#include <iostream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "missing_frames.h"
#include "orb/cli/frame_spec.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/scene_reading.h"
#include "orb/cli/legend_output.h"
#include "orb/cli/sphere_style_options.h"
#include "orb/cli/tool_main.h"
#include "orb/job/frame_jobs.h"

using orb::cli::UsageError;

namespace {

struct Settings {
    std::string list;
    std::string pattern;
    bool paths = false;
    bool missing = false;
    std::string scene;
    // How --scene is read, as orb-render reads it: every importer's options, --environment, --allow-empty.
    orb::cli::SceneReading reading;
    orb::cli::SphereStyleArguments style;  // --color-by, --radius-scale, ...: the --scene styled as orb-render styles it
    orb::request::RequestOptions render;  // the render the frames are asked to hold
};

// Whether any option of the render asked for was given.
bool any_render_option(const Settings& s) {
    return !s.scene.empty() || s.reading.import.allow_empty || s.render != orb::request::RequestOptions{} ||
           orb::cli::any_scene_reading_option(s.reading) || !orb::cli::sphere_style_options(s.style).empty();
}

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
                         "Only the frames that orb-render --skip-existing with the same options would render: "
                         "absent, stopped short, damaged, or another render");
            app.add_option("--scene", s.scene,
                           "With --missing: the scene orb-render renders, so that its content, camera and render "
                           "block are compared too")
                ->option_text("SCENE");
            app.add_flag("--allow-empty", s.reading.import.allow_empty,
                         "With --scene: accept a scene without spheres, as orb-render does");
            orb::cli::add_scene_reading_options(app, s.reading);
            orb::cli::add_sphere_style_options(app, s.style);
            orb::request::add_request_options(app, s.render);
            app.add_option("--samples", samples, "Older name of --sample-range")->option_text("START:COUNT");
            app.footer(
                "Prints one frame number (or with --paths one file name) per line, in the list's order.\n"
                "Examples:\n"
                "  for f in $(orb-frames 1-240x2); do orb-render shot.json --frame $f -o beauty.%04d.exr; done\n"
                "  orb-frames 1-240 shots/beauty.%04d.exr --missing           # frames still to render\n"
                "  orb-frames 1-240 shots/beauty.####.exr --missing --spp 256 --paths\n"
                "  orb-frames 1-240 shots/beauty.%04d.exr --missing --scene shot.glb --spp 256 --passes all\n"
                "Frame lists and patterns: docs/frames.md.\n"
                "Exit status: 0 success (whether or not frames are missing), 1 output failed, 2 usage error.");
        },
        [&]() -> int {
            if (samples) {
                if (s.render.sample_range) throw UsageError("--samples is --sample-range's older name; give one");
                s.render.sample_range = canonical_sample_range(*samples);
            }
            if ((s.paths || s.missing) && s.pattern.empty())
                throw UsageError(std::string(s.missing ? "--missing" : "--paths") + " needs a PATTERN, e.g. beauty.%04d.exr");
            if (any_render_option(s) && !s.missing)
                throw UsageError("--scene and the render's options (--spp, --width, --passes, ...) go with --missing");
            if (s.scene.empty() && (s.render.camera != orb::cli::CameraOptions{} || s.render.orbit.degrees))
                throw UsageError("the camera options (--camera-position, --orbit, ...) change the scene's camera: "
                                 "give --scene SCENE to compare it");
            orb::request::check_request_options(s.render);
            if (!s.pattern.empty() && orb::cli::count_frame_fields(s.pattern) == 0)
                throw UsageError("'" + s.pattern + "' has no frame number: write %04d or #### where it goes");
            const std::string frames = list_text(s.list);
            const orb::cli::FrameSpec spec = orb::cli::parse_frame_spec(frames);
            if (!s.style.legend.empty() && s.scene.empty())
                throw UsageError("--legend needs --scene SCENE: the legend is of the scene's colours");
            std::optional<orb::cli::LegendOutput> legend =
                orb::cli::LegendOutput::prepare(s.style, {{"--scene", s.scene}});
            std::optional<orb::frames::MissingFrames> judge;
            if (s.missing) judge.emplace(s.scene, s.render, frames, s.reading,
                                        orb::cli::sphere_style_options(s.style));
            if (legend) legend->write(judge->styled(), s.scene, s.style.color_range.empty() && judge->frames_differ());
            std::vector<orb::job::Job> jobs = orb::job::jobs_of({spec.begin(), spec.end()}, "", [&](long frame) {
                return s.pattern.empty() ? "" : orb::cli::expand_frame_pattern(s.pattern, static_cast<int>(frame));
            });
            // What orb-render --skip-existing would render, by its rule (a present file that does not count says why).
            if (judge)
                jobs = orb::job::unfinished(
                    jobs, [&](const orb::job::Job& job) { return judge->judge(job.output, *job.frame); },
                    [](orb::job::MessageKind, const std::string& note) { orb::cli::info(note); });
            std::string out;
            for (const orb::job::Job& job : jobs) out += (s.paths ? job.output : std::to_string(*job.frame)) + '\n';
            return orb::cli::print_to_stdout(out);
        });
}
