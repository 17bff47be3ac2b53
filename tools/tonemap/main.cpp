// orb-tonemap: scene-linear renders -> display images through OpenColorIO.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <iostream>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "orb/cli/frame_spec.h"
#include "orb/cli/io.h"
#include "orb/cli/messages.h"
#include "orb/cli/output_file.h"
#include "orb/cli/output_overlap.h"
#include "orb/cli/number_checks.h"
#include "orb/cli/tool_main.h"
#include "orb/image/alpha_output.h"
#include "orb/image/auto_exposure.h"
#include "orb/image/color_options.h"
#include "orb/image/contact_sheet.h"
#include "orb/image/display_currency.h"
#include "orb/image/display_record.h"
#include "orb/image/display_settings.h"
#include "orb/image/load.h"
#include "orb/image/passes.h"
#include "orb/image/source_identity.h"
#include "orb/image/tonemap.h"
#include "orb/image/write.h"
#include "orb/scene/error.h"

namespace fs = std::filesystem;
using namespace orb::image;
using orb::cli::UsageError;

namespace {

struct Settings {
    std::vector<std::string> inputs;
    std::string output;
    std::string pass = "beauty";
    double exposure = 0.0;
    std::string format;
    int bits = 0;
    bool no_dither = false;
    std::string frames;
    bool skip_existing = false;
    bool missing = false;
    bool contact_sheet = false;
    bool transparent = false;
    std::string background;  // --background as typed
    bool auto_exposure = false;
    ColorOptions color;

    AlphaOutput alpha() const {
        AlphaOutput out;
        if (transparent) out.mode = AlphaMode::Transparent;
        if (!background.empty()) {
            out.mode = AlphaMode::OverColor;
            out.background = parse_background_color(background);
        }
        return out;
    }
};

// The tiles of a sheet of frames are shrunk by a whole factor to at most
// this wide, so that 48 frames of 1080p make a sheet a screen can show.
constexpr int kFrameTileMaxWidth = 480;

// One picture of a sheet of frames: its input and its label.
struct SheetSource {
    std::string input, label;
};

// --contact-sheet with --frames and an output without a frame number, or
// with several inputs and an output that is not a folder: one sheet of
// frames (or files) instead of one sheet of passes per input.
std::vector<SheetSource> frame_sheet_sources(const Settings& s) {
    if (!s.contact_sheet) return {};
    std::vector<SheetSource> sources;
    if (!s.frames.empty()) {
        if (s.output != "-" && orb::cli::count_frame_fields(s.output) > 0) return {};
        if (s.inputs.size() != 1 || s.inputs[0] == "-" || orb::cli::count_frame_fields(s.inputs[0]) == 0)
            throw UsageError("--frames needs one input pattern with a frame number, e.g. beauty.%04d.exr");
        for (int frame : orb::cli::parse_frame_spec(s.frames))
            sources.push_back({orb::cli::expand_frame_pattern(s.inputs[0], frame), std::to_string(frame)});
        return sources;
    }
    std::error_code ec;
    if (s.inputs.size() < 2 || fs::is_directory(s.output, ec)) return {};
    for (const std::string& in : s.inputs) {
        if (in == "-") throw UsageError("'-' (stdin) cannot be one of several inputs");
        sources.push_back({in, fs::path(in).stem().string()});
    }
    return sources;
}

struct Job {
    std::string input, output;
    std::optional<int> frame;  // with --frames
};

std::vector<Job> plan_jobs(const Settings& s) {
    std::vector<Job> jobs;
    if (!s.frames.empty()) {
        if (s.inputs.size() != 1 || s.inputs[0] == "-" || orb::cli::count_frame_fields(s.inputs[0]) == 0)
            throw UsageError("--frames needs one input pattern with a frame number, e.g. beauty.%04d.exr");
        if (s.output == "-" || orb::cli::count_frame_fields(s.output) == 0)
            throw UsageError("--frames needs an output pattern with a frame number, e.g. -o beauty.%04d.png");
        for (int frame : orb::cli::parse_frame_spec(s.frames))
            jobs.push_back({orb::cli::expand_frame_pattern(s.inputs[0], frame),
                            orb::cli::expand_frame_pattern(s.output, frame), frame});
        return jobs;
    }
    if (s.inputs.size() == 1) return {{s.inputs[0], s.output, std::nullopt}};
    std::error_code ec;
    if (!fs::is_directory(s.output, ec))
        throw UsageError("with several inputs, -o must be an existing directory (got '" + s.output + "')");
    const std::string ext = s.format.empty() ? "png" : s.format;
    for (const std::string& in : s.inputs) {
        if (in == "-") throw UsageError("'-' (stdin) cannot be one of several inputs");
        jobs.push_back({in, (fs::path(s.output) / (fs::path(in).stem().string() + "." + ext)).string(), std::nullopt});
    }
    return jobs;
}

// Every output against every input (and the colour config), before any work.
void refuse_overlaps(const std::vector<Job>& jobs, const Settings& s) {
    std::vector<orb::cli::NamedPath> inputs, outputs;
    for (const Job& job : jobs) {
        inputs.push_back({"input", job.input});
        outputs.push_back({"-o", job.output});
    }
    if (!s.color.config_path.empty()) inputs.push_back({"--config", s.color.config_path});
    orb::cli::refuse_overlapping_paths(inputs, outputs);
}

// The command line's write options for one output (format unchecked).
WriteOptions write_options_for(const Job& job, const Settings& s) {
    WriteOptions options;
    options.format = s.format.empty() ? extension_of(job.output) : s.format;
    options.bits = s.bits;
    options.dither = !s.no_dither;
    return options;
}

// A format and --bits that cannot go together (--bits 16 for a JPEG) are a
// mistake on the command line, found before any work: each format once.
void check_formats(const std::vector<Job>& jobs, const Settings& s) {
    std::set<std::string> checked;
    for (const Job& job : jobs) {
        const WriteOptions options = write_options_for(job, s);
        if (options.format.empty() || !checked.insert(options.format).second) continue;  // empty: reported with the job
        try {
            checked_write_options(options);
        } catch (const orb::InputError& e) {
            throw UsageError(e.what());
        }
    }
}

// The settings an output is made with, resolved as tonemap_one resolves
// them, so that what is recorded in an image and what a later run asks for
// compare alike: the display and view defaults filled in (asking for the
// default view by name is asking for the same image), --input-space by its
// canonical name ("" = the input's own, which its identity and the config
// decide), dithering only where it applies (8 bits).
DisplaySettings settings_for(const WriteOptions& options, const Settings& s, const ColorConfig& config) {
    DisplaySettings d;
    // A sheet of frames shows one pass of each; a sheet of passes every pass of one input.
    const bool sheet_of_passes = s.contact_sheet && frame_sheet_sources(s).empty();
    d.contact_sheet = s.contact_sheet;
    d.pass = sheet_of_passes ? "" : s.pass;
    if (!s.color.input_space.empty()) {
        d.input_space = config.resolve_color_space(s.color.input_space);
        if (d.input_space.empty()) d.input_space = s.color.input_space;  // unknown: tonemap_one reports it
    }
    d.display = s.color.display.empty() ? config.default_display() : s.color.display;
    d.view = s.color.view.empty() ? config.default_view(d.display) : s.color.view;
    d.look = s.color.look;
    d.exposure = s.exposure;
    d.auto_exposure = s.auto_exposure;
    d.alpha = alpha_output_text(s.alpha());
    d.config = config.content_hash();
    d.format = options.format;
    d.bits = options.bits;
    d.dither = options.dither && options.bits == 8;
    return d;
}

// Whether the output of `job` is current (display_currency.h has the rule).
// An output whose format cannot be written counts as absent: tonemap_one
// reports the bad format with this output.
DisplayImageVerdict judge(const Job& job, const Settings& s, const ColorConfig& config) {
    DisplaySettings asked;
    try {
        asked = settings_for(checked_write_options(write_options_for(job, s)), s, config);
    } catch (const std::exception&) {
        return {DisplayImageVerdict::Kind::Absent, {}};
    }
    return judge_display_image(job.output, job.input, asked);
}

// --skip-existing: whether to leave the output of `job` alone. One line says
// why an existing output is made again; that the input has no identity
// (stdin) is said once.
bool is_current(const Job& job, const Settings& s, const ColorConfig& config, bool& said_cannot_judge) {
    const DisplayImageVerdict verdict = judge(job, s, config);
    using Kind = DisplayImageVerdict::Kind;
    switch (verdict.kind) {
        case Kind::Current:
            return true;
        case Kind::Absent:
            return false;
        case Kind::Damaged:
            orb::cli::warning(verdict.reason + "; making it again");
            return false;
        case Kind::Stale:
            orb::cli::info(job.output + ": " + verdict.reason + ": making it again");
            return false;
        case Kind::CannotJudge:
            if (!said_cannot_judge) orb::cli::info("--skip-existing: " + verdict.reason + ": making it");
            said_cannot_judge = true;
            return false;
    }
    return false;
}

// --missing: the outputs --skip-existing would make, without making them:
// their frame numbers (with --frames) or output paths on stdout, one a line,
// and for each that exists one line on stderr saying why it is not current.
int list_missing(const std::vector<Job>& jobs, const Settings& s, const ColorConfig& config) {
    using Kind = DisplayImageVerdict::Kind;
    std::string out;
    bool said_cannot_judge = false;
    for (const Job& job : jobs) {
        const DisplayImageVerdict verdict = judge(job, s, config);
        if (verdict.kind == Kind::Current) continue;
        const std::string label = job.frame ? "frame " + std::to_string(*job.frame) + ": " : "";
        switch (verdict.kind) {
            case Kind::Stale:
                orb::cli::info(label + job.output + ": " + verdict.reason);
                break;
            case Kind::Damaged:
                orb::cli::info(label + job.output + ": does not read whole (" + verdict.reason + ")");
                break;
            case Kind::CannotJudge:
                if (!said_cannot_judge) orb::cli::info("--missing: " + verdict.reason);
                said_cannot_judge = true;
                break;
            case Kind::Current:
            case Kind::Absent:
                break;
        }
        out += (job.frame ? std::to_string(*job.frame) : job.output) + "\n";
    }
    return orb::cli::print_to_stdout(out);
}

// A number in a message: four significant digits.
std::string number(double value) {
    std::ostringstream out;
    out << std::setprecision(4) << value;
    return out.str();
}

// --auto-exposure over the colour `picture` (scene-linear, as the view takes
// it), added to --exposure; one line says what it came to.
double exposure_for(const Settings& s, const std::vector<const Image*>& pictures, const ColorConfig& config,
                    const std::string& what) {
    if (!s.auto_exposure) return s.exposure;
    double log_sum = 0.0;
    std::size_t pixels = 0;
    for (const Image* picture : pictures) {
        const AutoExposure a = auto_exposure(*picture, config.luma_coefficients());
        if (a.pixels) log_sum += std::log(a.log_average) * static_cast<double>(a.pixels);
        pixels += a.pixels;
    }
    if (pixels == 0) {
        orb::cli::warning(what + ": no pixel brighter than black; --auto-exposure leaves the exposure at " +
                          number(s.exposure));
        return s.exposure;
    }
    const double mean_log = log_sum / static_cast<double>(pixels);
    const double stops =
        std::clamp((std::log(kMiddleGrey) - mean_log) / std::log(2.0) + s.exposure, -100.0, 100.0);
    orb::cli::info(what + ": --auto-exposure: log-average luminance " + number(std::exp(mean_log)) +
                   ", exposure " + number(stops) + " stops");
    return stops;
}

// The pass `name` of `loaded`, with its alpha made what the settings ask.
Pass shown_pass(const LoadedImage& loaded, const std::string& name, const Settings& s, const std::string& input) {
    const Pass pass = extract_pass(loaded.image, name, display_name(input));
    if (!pass.has_alpha && (s.transparent || !s.background.empty()))
        orb::cli::warning(display_name(input) + ": pass " + pass.name + " has no alpha; " +
                          (s.transparent ? "--transparent" : "--background") + " changes nothing");
    if (pass.kind != PassKind::Color && s.auto_exposure)
        orb::cli::warning(display_name(input) + ": pass " + pass.name + " is data, not light; --auto-exposure ignored");
    return prepare_alpha(pass, loaded, s.alpha());
}

// For a sheet of passes: the input with its beauty R, G, B (and A) replaced
// by what the beauty pass shows (with --background, the spheres over it).
Image with_beauty_shown(const LoadedImage& loaded, const Settings& s, const std::string& input) {
    if (s.background.empty()) return loaded.image;
    const Pass shown = shown_pass(loaded, "beauty", s, input);
    Image image = loaded.image;
    const int r = image.find_channel("R"), g = image.find_channel("G"), b = image.find_channel("B");
    const int a = image.find_channel("A");
    if (r < 0 || g < 0 || b < 0) return image;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            image.at(x, y, r) = shown.image.at(x, y, 0);
            image.at(x, y, g) = shown.image.at(x, y, 1);
            image.at(x, y, b) = shown.image.at(x, y, 2);
            if (a >= 0) image.at(x, y, a) = 1.0f;
        }
    return image;
}

WriteOptions output_options(const Job& job, const Settings& s) {
    WriteOptions options = checked_write_options(write_options_for(job, s));
    options.premultiply_alpha = options.format == "exr";  // PNG and TIFF keep straight alpha
    return options;
}

void tonemap_one(const Job& job, const Settings& s, const ColorConfig& config) {
    WriteOptions options = output_options(job, s);
    orb::cli::OutputFile output(job.output, "-o");  // fails now, before the work, if it cannot be written

    // The input's identity is taken before its pixels are read: if it is
    // replaced meanwhile, the image records the older file and the next
    // --skip-existing run makes it again, rather than keeping a stale one.
    const SourceLookup source = identify_source(job.input);
    DisplayRecord record;
    record.source_is_file = source.state == SourceLookup::State::File;
    record.source = source.identity;
    record.settings = settings_for(options, s, config);
    options.record = format_display_record(record);

    const LoadedImage loaded = load_image(job.input);
    DisplayView request{input_space_for(config, s.color, loaded), s.color.display, s.color.view, s.color.look,
                        s.exposure};
    DisplayView view = resolve_display_view(config, request);

    Image picture;
    if (s.contact_sheet) {
        if (s.auto_exposure) {
            const Pass beauty = shown_pass(loaded, "beauty", s, job.input);
            view.exposure_stops = exposure_for(s, {&beauty.image}, config, display_name(job.input));
        }
        picture = make_contact_sheet(with_beauty_shown(loaded, s, job.input), config, view);
    } else {
        const Pass pass = shown_pass(loaded, s.pass, s, job.input);
        if (pass.kind == PassKind::Color) view.exposure_stops = exposure_for(s, {&pass.image}, config, display_name(job.input));
        picture = tonemap_pass(pass, config, view);
    }

    output.write(encode_image(picture, options));
    orb::cli::info("wrote " + output.display_name());
}

// One sheet of one pass of many frames (or files), under their labels; one
// exposure for all (--auto-exposure over all of them), so frames compare.
void make_frame_sheet(const std::vector<SheetSource>& sources, const Settings& s, const ColorConfig& config) {
    const Job job{sources.front().input, s.output, std::nullopt};
    WriteOptions options = output_options(job, s);
    orb::cli::OutputFile output(s.output, "-o");
    DisplayRecord record;
    record.source_is_file = false;  // many sources: --skip-existing does not judge a sheet of frames
    record.settings = settings_for(options, s, config);
    options.record = format_display_record(record);

    std::vector<Pass> passes;
    std::optional<DisplayView> view;
    for (const SheetSource& source : sources) {
        const LoadedImage loaded = load_image(source.input);
        if (!view) {
            const DisplayView request{input_space_for(config, s.color, loaded), s.color.display, s.color.view,
                                      s.color.look, s.exposure};
            view = resolve_display_view(config, request);
        }
        Pass pass = shown_pass(loaded, s.pass, s, source.input);
        const int factor = (pass.image.width + kFrameTileMaxWidth - 1) / kFrameTileMaxWidth;
        // Light averages; labels, depths and normals are picked, not blended.
        pass.image = pass.kind == PassKind::Color ? box_downscale(pass.image, factor) : nearest_downscale(pass.image, factor);
        passes.push_back(std::move(pass));
    }
    if (passes.front().kind == PassKind::Color) {
        std::vector<const Image*> pictures;
        for (const Pass& pass : passes) pictures.push_back(&pass.image);
        view->exposure_stops = exposure_for(s, pictures, config, "contact sheet");
    }
    std::vector<SheetTile> tiles;
    for (std::size_t i = 0; i < passes.size(); ++i) {
        tiles.push_back({sources[i].label, tonemap_pass(passes[i], config, *view)});
    }
    output.write(encode_image(lay_out_sheet(tiles), options));
    orb::cli::info("wrote " + output.display_name());
}

}  // namespace

int main(int argc, char** argv) {
    Settings s;
    return orb::cli::run_tool(
        argc, argv, "orb-tonemap", "Turn scene-linear renders (EXR or any OIIO format) into display images through OpenColorIO",
        [&](CLI::App& app) {
            app.add_option("inputs", s.inputs, "Input image(s), '-' for stdin, or a %04d pattern with --frames");
            app.add_option("-o,--output", s.output, "Output file ('-' = stdout, needs --format), or a directory for several inputs")
                ->option_text("OUT");
            app.add_option("--pass,--layer", s.pass,
                           "Pass to show: beauty, direct, indirect, emission, albedo, normal, depth, variance, id, background, denoised, or any layer name")
                ->option_text("NAME");
            // +-100 stops keeps the gain 2^STOPS a normal float (7.9e-31 ... 1.3e30).
            app.add_option("--exposure", s.exposure, "Exposure adjustment in stops (-100 ... 100), applied in scene-linear")
                ->option_text("STOPS")
                ->check(orb::cli::finite_number_in(-100, 100, "a number of stops in [-100, 100]"));
            add_color_options(app, s.color);
            app.add_option("--format", s.format, "Output format: png, jpg, tif, exr, ... (default: from the output's extension)")
                ->option_text("FMT");
            app.add_option("--bits", s.bits, "Bits per channel: 8 or 16 (PNG, TIFF), 16 or 32 (EXR)")
                ->option_text("N")
                ->check(orb::cli::one_of({8, 16, 32}));
            app.add_flag("--no-dither", s.no_dither, "Round instead of dithering when quantising to 8 bits");
            app.add_option("--frames", s.frames,
                           "Frames for pattern inputs/outputs (%04d or ####): 1-240, 1-240x2, 1,5,9-12")
                ->option_text("LIST");
            app.add_flag("--skip-existing", s.skip_existing,
                         "Leave outputs alone that are current: whole, made from the file now at their input path "
                         "with these settings (an output whose input is gone is kept)");
            app.add_flag("--missing", s.missing,
                         "Make nothing: print the frames (with --frames; else the outputs) whose output is not "
                         "current, as --skip-existing judges it, one a line, with why on stderr");
            app.add_flag("--contact-sheet", s.contact_sheet,
                         "Lay out all passes of the input in one labelled image; with --frames and an output "
                         "without a frame number, or several inputs and an output file, one pass of every frame");
            app.add_flag(
                "--transparent", s.transparent,
                "Show the spheres alone, their coverage as alpha (default: opaque, what the camera sees)");
            app.add_option("--background", s.background,
                           "Show the spheres over this colour, opaque: R,G,B scene-linear, or #rrggbb sRGB")
                ->option_text("COLOR")
                ->check([](const std::string& text) {
                    try {
                        parse_background_color(text);
                        return std::string();
                    } catch (const std::exception& e) {
                        return std::string(e.what());
                    }
                });
            app.add_flag("--auto-exposure", s.auto_exposure,
                         "Expose the log-average luminance to middle grey 0.18 (--exposure adds to it)");
            app.footer(
                "Examples:\n"
                "  orb-tonemap render.exr -o render.png\n"
                "  orb-import cornell.scn | orb-render - -o - | orb-tonemap - -o cornell.png\n"
                "  orb-tonemap render.exr --view Filmic --exposure 1 -o render.jpg\n"
                "  orb-tonemap render.exr --display 'Display P3' --view 'ACES 1.0 - SDR Video' -o p3.png --bits 16\n"
                "  orb-tonemap render.exr --pass normal -o normals.png\n"
                "  orb-tonemap render.exr --contact-sheet -o passes.png\n"
                "  orb-tonemap beauty.%04d.exr --frames 1-48x4 --contact-sheet -o sheet.png\n"
                "  orb-tonemap render.exr --transparent -o render.png\n"
                "  orb-tonemap render.exr --background 0.18,0.18,0.18 --auto-exposure -o render.jpg\n"
                "  orb-tonemap beauty.%04d.exr --frames 1-240 -o png/beauty.%04d.png\n"
                "  orb-tonemap beauty.####.exr --frames 1-240 --skip-existing -o png/beauty.####.png\n"
                "  orb-tonemap beauty.####.exr --frames 1-240 --missing -o png/beauty.####.png\n"
                "  orb-tonemap a.exr b.exr c.exr -o previews/ --format jpg\n"
                "  orb-tonemap render.exr -o - --format png > render.png\n"
                "  orb-tonemap --list\n"
                "Colour config: --config FILE, else $OCIO, else Orb's share/orb/ocio/config.ocio.\n"
                "Exit status: 0 success, 1 an input could not be read or an output written, 2 usage error.");
        },
        [&]() -> int {
            if (s.color.list) {
                return orb::cli::print_to_stdout(load_color_config(s.color).listing());
            }
            if (s.inputs.empty()) throw UsageError("no input image (see --help)");
            if (s.output.empty()) throw UsageError("no output: give -o OUT");
            if (s.output == "-" && s.format.empty()) throw UsageError("-o - (stdout) needs --format, e.g. --format png");
            const std::vector<SheetSource> sheet_sources = frame_sheet_sources(s);
            if (s.contact_sheet && sheet_sources.empty() && s.pass != "beauty")
                throw UsageError("--contact-sheet shows every pass; drop --pass");
            if (s.transparent && !s.background.empty())
                throw UsageError("--transparent keeps the uncovered parts transparent, --background fills them: give one");
            if (s.contact_sheet && s.transparent)
                throw UsageError("a contact sheet is opaque; drop --transparent (--background shows the spheres over a colour)");
            if (!sheet_sources.empty()) {
                if (s.skip_existing || s.missing)
                    throw UsageError("--skip-existing and --missing judge one source per output, not a sheet of frames");
                check_formats({{sheet_sources.front().input, s.output, std::nullopt}}, s);
                std::vector<orb::cli::NamedPath> inputs;
                for (const SheetSource& source : sheet_sources) inputs.push_back({"input", source.input});
                if (!s.color.config_path.empty()) inputs.push_back({"--config", s.color.config_path});
                orb::cli::refuse_overlapping_paths(inputs, {{"-o", s.output}});
                make_frame_sheet(sheet_sources, s, load_color_config(s.color));
                return orb::cli::kSuccess;
            }
            if (s.missing && s.output == "-") throw UsageError("--missing needs an output file, not -o -");
            const std::vector<Job> jobs = plan_jobs(s);
            check_formats(jobs, s);
            refuse_overlaps(jobs, s);
            const ColorConfig config = load_color_config(s.color);
            if (s.missing) return list_missing(jobs, s, config);
            // Sequences: a bad frame is reported and the rest still get done.
            int failures = 0, skipped = 0;
            bool said_cannot_judge = false;
            for (const Job& job : jobs) {
                if (s.skip_existing && is_current(job, s, config, said_cannot_judge)) {
                    ++skipped;
                    continue;
                }
                try {
                    tonemap_one(job, s, config);
                } catch (const std::exception& e) {
                    if (jobs.size() == 1) throw;  // one image: run_tool maps the error to its exit code
                    orb::cli::error(e.what());
                    ++failures;
                }
            }
            if (skipped)
                orb::cli::info("skipped " + std::to_string(skipped) + " of " + std::to_string(jobs.size()) +
                               (skipped == 1 ? " output that is current" : " outputs that are current"));
            if (failures) orb::cli::error(std::to_string(failures) + " of " + std::to_string(jobs.size()) + " images failed");
            return failures ? orb::cli::kFailure : orb::cli::kSuccess;
        });
}
