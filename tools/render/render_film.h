// One image: the progressive loop on a renderer that holds the scene, with
// checkpoints and progress, then the final write. Shared by a single render
// and by every frame of an animation.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "frame_claim.h"
#include "orb/cli/output_file.h"
#include "orb/denoise/denoise_film.h"
#include "orb/exr/film_exr.h"
#include "orb/render/adaptive_sampler.h"
#include "orb/render/progressive.h"
#include "orb/render/renderer.h"
#include "render_options.h"
#include "render_plan.h"
#include "run_stats.h"

namespace orb::render_cli {

std::string device_label(const render::DeviceInfo& device);
// Every device of the renderer: "NAME (PLATFORM)", joined by "; ".
std::string devices_label(const render::Renderer& renderer);
// The line orb-render prints once its renderer exists: "device: NAME (PLATFORM)",
// or "devices: A; B" for several.
std::string devices_line(const render::Renderer& renderer);
const char* stop_reason_name(render::StopReason reason);
std::string kernel_builds_text(int builds);  // "1 kernel build", "2 kernel builds"

// The final image of a render, ready to be encoded and written once its
// film has arrived (a frame's film travels back while the next frame renders).
struct FinalImage {
    Film film;
    exr::ExrMetadata metadata;
    exr::ExrWriteOptions options;
    std::optional<render::PendingFilm> arriving;  // set while the film is on its way
    // --denoise: adds the denoised layer to the encoded image (final images
    // only, never checkpoints), and sets *denoise_times to what the layer
    // took (shared, so that a frame's stats can read it once its background
    // write is done).
    std::shared_ptr<denoise::Denoiser> denoiser = nullptr;
    std::shared_ptr<denoise::DenoiseTimes> denoise_times = nullptr;

    bool checkpoint = false;  // written while rendering: its sums' range is reported with the final image

    // Waits for the film, if it is still on its way; a final image then
    // warns of sums that reached the film's range.
    void wait_for_film() {
        if (arriving) arriving->wait(film);
        arriving.reset();
        if (!checkpoint) warn_of_sums_out_of_range();
    }
    std::string encode() {
        wait_for_film();
        return exr::encode_film_exr(film, metadata, options, post_layers());
    }
    // The file's bytes, valid until `into` encodes again.
    std::string_view encode(exr::ExrEncoding& into) {
        wait_for_film();
        exr::encode_film_exr(film, metadata, options, into, post_layers());
        return into.bytes();
    }

private:
    void warn_of_sums_out_of_range() const;

    // The denoised layer is written by the one encode of the film.
    std::vector<exr::PostLayerPlanes> post_layers() const {
        if (!denoiser) return {};
        return {denoise::denoised_post_layer(*denoiser, "the rendered image", denoise_times)};
    }
};

struct FilmOutcome {
    render::StopReason reason = render::StopReason::ReachedSpp;
    bool rendered = false;  // false when stopped before the first pass finished
    RunStats stats;
    FinalImage image;       // when rendered; the caller writes it
};

// Renders `plan` to its target on `renderer` (its scene, seed and film set
// up by the caller), writing checkpoints to `image`, and returns the final
// image for the caller to write, read into `reuse` (whose memory a frame
// loop hands back frame after frame). With `read_later` the image's film is
// still on its way when this returns (FinalImage::wait_for_film), so the
// renderer can go on to the next frame. `label` starts the progress lines; a
// `claim` is refreshed while rendering.
FilmOutcome render_film(render::Renderer& renderer, const RenderPlan& plan, const RenderOptions& options,
                        cli::OutputFile& image, const std::string& label, FrameClaim* claim,
                        Film reuse = {}, bool read_later = false);

// "64 spp (samples 64:64) in 2.1 s (1.3 Msamples/s) -> out.exr"
std::string film_summary(const FilmOutcome& outcome, const render::Renderer& renderer, const cli::OutputFile& image);

}  // namespace orb::render_cli
