#include "orb/request/request_options.h"

#include <charconv>
#include <climits>
#include <cmath>
#include <stdexcept>

#include "orb/cli/tool_main.h"
#include "orb/exr/passes.h"
#include "orb/film/sample_ranges.h"
#include "orb/tables/render_names.h"

namespace orb::request {
namespace {

// A seed is any 64-bit value, written in decimal. CLI11 alone would wrap -1 to
// 2^64-1 and clamp larger values, so distinct seeds would collide: only plain
// digits that fit are accepted.
const CLI::Validator kSeed(
    [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        if (!text.empty() && error == std::errc{} && stop == end) return {};
        return "expected a whole number in [0, 18446744073709551615], got '" + text + "'";
    },
    "0..2^64-1");

// START:COUNT, COUNT within what orb:spp (an EXR int) can record.
const CLI::Validator kSampleRange(
    [](std::string& text) -> std::string {
        try {
            const SampleRange range = parse_sample_range(text);
            if (range.count > static_cast<std::uint64_t>(INT_MAX))
                return "COUNT must be at most 2147483647 (orb:spp is an EXR int), got '" + text + "'";
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return {};
    },
    "START:COUNT");

}  // namespace

const CLI::Validator& positive_number() {
    static const CLI::Validator validator(
        [](std::string& text) -> std::string {
            try {
                std::size_t used = 0;
                const double value = std::stod(text, &used);
                if (used == text.size() && std::isfinite(value) && value > 0) return {};
            } catch (const std::exception&) {
            }
            return "expected a positive number of seconds, got '" + text + "'";
        },
        "SECONDS>0");
    return validator;
}

void add_request_options(CLI::App& app, RequestOptions& o) {
    app.add_option("--spp", o.spp, "Samples per pixel (default: the scene's render.spp)")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{INT_MAX}));
    app.add_option("--sample-range", o.sample_range,
                   "Exactly the samples START ... START+COUNT-1 (a slice of a frame, for orb-merge)")
        ->check(kSampleRange);
    app.add_option("--seed", o.seed, "Random seed, 0 ... 2^64-1 (default 0)")->check(kSeed);
    app.add_option("--mode", o.mode, "Light transport: global (path tracing, default) or direct")
        ->check(CLI::IsMember(device::names_in(device::kIntegratorModeNames)));
    app.add_option("--sampler", o.sampler, "Random numbers: sobol (low discrepancy, default) or independent")
        ->check(CLI::IsMember(device::names_in(device::kSamplerNames)));
    app.add_option("--max-depth", o.max_depth, "Maximum path depth (default: the scene's render.max_depth)")
        ->check(CLI::Range(0, 1024));
    app.add_option("--width", o.width, "Image width (default: the scene's render.width)")->check(CLI::Range(1, 65536));
    app.add_option("--height", o.height, "Image height (default: the scene's render.height)")
        ->check(CLI::Range(1, 65536));
    app.add_option("--passes", o.passes,
                   "Layers to write (only these are computed): beauty (default), direct, indirect, emission, albedo, "
                   "normal, depth, variance, id, or all")
        ->option_text("LIST");
    app.add_flag("--half", o.half, "Store colour layers as HALF (Z and id stay FLOAT; not resumable)");
    app.add_option("--fps", o.fps, "Frames per second for --frame/--frames (default 24)")
        ->check(positive_number())
        ->option_text("FPS");
    app.add_flag("--same-seed", o.same_seed, "Every frame with --seed itself, not a seed derived from the frame");
    cli::add_camera_options(app, o.camera);
    cli::add_orbit_options(app, o.orbit);
}

void check_request_options(const RequestOptions& o) {
    if (o.passes) {
        try {
            exr::parse_passes(*o.passes);
        } catch (const std::invalid_argument& e) {
            throw cli::UsageError(std::string("--passes: ") + e.what());
        }
    }
    if (o.sample_range && o.spp)
        throw cli::UsageError("--sample-range START:COUNT already says how many samples to render; drop --spp " +
                              std::to_string(*o.spp));
}

job::RequestSettings resolve_request(const RequestOptions& o, const RenderSettings* scene,
                                     const std::string* animation_frames, bool renders_frames) {
    job::GivenSettings given;
    given.width = o.width;
    given.height = o.height;
    given.max_depth = o.max_depth;
    given.spp = o.spp;
    if (o.sample_range) given.sample_range = parse_sample_range(*o.sample_range);
    given.seed = o.seed;
    given.mode = o.mode;
    given.sampler = o.sampler;
    if (o.passes) given.passes = exr::parse_passes(*o.passes);
    given.half = o.half;
    given.fps = o.fps;
    given.same_seed = o.same_seed;
    job::RequestSettings s = job::resolve_settings(given, scene);
    s.camera.apply = [camera = o.camera](Scene& posed, int width, int height, const std::string& label) {
        cli::apply_camera_options(camera, posed, width, height, label);
    };
    if (std::optional<cli::Orbit> orbit = cli::resolve_orbit(o.orbit, animation_frames, renders_frames))
        s.camera.turn = [orbit = *orbit](const Camera& camera, long frame) { return orbit.turn(camera, frame); };
    return s;
}

}  // namespace orb::request
