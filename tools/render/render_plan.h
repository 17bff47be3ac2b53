// What orb-render will do: the scene at the requested time, the renderer's
// settings and the output's, with everything a resumed EXR dictates applied
// and checked against the command line.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "orb/exr/film_exr.h"
#include "orb/render/renderer.h"
#include "orb/scene/scene.h"
#include "render_options.h"

namespace orb::render_cli {

struct RenderPlan {
    Scene scene;                // at scene_time
    std::string scene_label;    // the path, or <stdin>
    std::string scene_hash;     // orb::scene_content_hash(scene)
    double scene_time = 0;
    render::RenderConfig config;
    std::uint64_t target_spp = 0;   // samples per pixel the film is to hold
    std::uint64_t first_sample = 0; // where a fresh render starts (--sample-range START)
    std::vector<exr::Pass> passes;
    bool half = false;
    std::optional<exr::ExrFilm> resumed;  // the film to continue from
};

// Reads and imports the scene, then applies the command line (and for
// --resume the file's header). Throws orb::InputError for bad input or a
// resume that would not continue the same render.
RenderPlan make_render_plan(const RenderOptions& options);

// The orb:* metadata for an image of this plan (render seconds and device filled by the caller).
exr::ExrMetadata plan_metadata(const RenderPlan& plan);

}  // namespace orb::render_cli
