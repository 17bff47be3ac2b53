// What a render job renders: each setting its front end gives (orb-render's
// command line: orb/request/request_options.h), else the scene's render
// block (size, spp, depth), else Orb's default; and from it the request for
// each output (render_request.h). orb-render renders with these settings
// and orb-frames --missing judges with them, so the same options mean the
// same render in both.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "orb/exr/render_request.h"
#include "orb/film/sample_ranges.h"
#include "orb/scene/scene.h"
#include "orb/tables/render_names.h"

namespace orb::job {

// Neither glTF (keyframe times in seconds) nor Orb's scene format records a
// frame rate, so without --fps frames are 1/24 s apart.
inline constexpr double kDefaultFps = 24.0;

// The layers written when --passes is not given: the beauty image alone, as
// production renderers write by default; the others are asked for by name.
const std::vector<exr::Pass>& default_passes();

// The scene time of a frame: frame / fps seconds.
double frame_time(long frame, double fps);

// The seed of a frame, so that noise does not stand still on screen:
// SplitMix64's finaliser of (seed XOR the finaliser of frame + 1). The same
// for --frame N and frame N of --frames.
std::uint64_t frame_seed(std::uint64_t seed, long frame);

// The camera a front end asks for (orb-render's --camera-position, --orbit,
// ...), as the job applies it to a posed scene: the same for every tool, so
// frame f has one camera whoever renders or judges it.
struct CameraRequest {
    // Replaces parts of the posed scene's camera for an image of width x
    // height; throws orb::InputError naming `label`. None: the scene's camera.
    std::function<void(Scene& posed, int width, int height, const std::string& label)> apply;
    // Then turns it to a frame (a turntable). None: the camera does not
    // move from frame to frame.
    std::function<Camera(const Camera& camera, long frame)> turn;
};

struct RequestSettings {
    // From the command line, else the scene's render block; empty only when
    // neither is known (orb-frames without --scene).
    std::optional<int> width, height, max_depth;
    std::optional<std::uint64_t> spp;  // samples asked for: --spp, a slice's COUNT, else render.spp
    bool slice = false;                // --sample-range: exactly [first_sample, first_sample + spp)
    std::uint64_t first_sample = 0;
    std::uint64_t seed = 0;            // --seed, the base of every frame's own seed
    std::string mode{device::kIntegratorModeNames.front().name};  // each table's first row is the default
    std::string sampler{device::kSamplerNames.front().name};
    std::vector<exr::Pass> passes = default_passes();
    bool half = false;
    double fps = kDefaultFps;
    bool same_seed = false;
    CameraRequest camera;

    std::uint64_t seed_of(std::optional<long> frame) const;  // a frame's seed, or --seed for a still
    // The request for one output: a frame of an animation, or a still at
    // `scene_time`. The caller adds the posed scene's identity.
    exr::RenderRequest request(std::optional<long> frame, double scene_time = 0) const;
};

// The settings a front end gives (orb-render's --width, --spp, ...); what it
// leaves out comes from the scene's render block, else Orb's default.
struct GivenSettings {
    std::optional<int> width, height, max_depth;
    std::optional<std::uint64_t> spp;
    std::optional<SampleRange> sample_range;  // --sample-range START:COUNT: a slice
    std::optional<std::uint64_t> seed;
    std::optional<std::string> mode, sampler;
    std::optional<std::vector<exr::Pass>> passes;
    bool half = false;
    std::optional<double> fps;
    bool same_seed = false;
};

// `scene_render` is the scene's render block, or null when the scene is not
// read. The camera stays the scene's (the front end sets `camera`).
RequestSettings resolve_settings(const GivenSettings& given, const RenderSettings* scene_render);

}  // namespace orb::job
