// One image: the progressive loop on a renderer that holds the scene, with
// checkpoints and progress, then the final write. Shared by a single render
// and by every frame of an animation.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "orb/denoise/denoise_film.h"
#include "orb/exr/film_exr.h"
#include "orb/job/messages.h"
#include "orb/job/render_plan.h"
#include "orb/job/run_stats.h"
#include "orb/render/adaptive_sampler.h"
#include "orb/render/progressive.h"
#include "orb/render/renderer.h"

namespace orb::job {

std::string device_label(const render::DeviceInfo& device);
// Every device of the renderer: "NAME (PLATFORM)", joined by "; ".
std::string devices_label(const render::Renderer& renderer);
// The line orb-render prints once its renderer exists: "device: NAME (PLATFORM)",
// or "devices: A; B" for several.
std::string devices_line(const render::Renderer& renderer);
const char* stop_reason_name(render::StopReason reason);
// The line said once an image is in place, by why its render stopped:
// "done: SUMMARY", "time limit reached: SUMMARY", "interrupted: wrote
// SUMMARY" (a warning); a still's line also names the adaptive goal it
// reached ("every pixel below --noise-threshold: ", "--target-error
// reached: "), a frame's says "done: " of it.
std::string written_line(render::StopReason reason, const std::string& summary, bool still);
std::string kernel_builds_text(int builds);  // "1 kernel build", "2 kernel builds"
// Whether a film holds the samples 0 ... n-1 in one range: the whole
// render from its start, not a slice (docs/orb-render.md, "Exact sums").
bool holds_samples_from_zero(const SampleRanges& held);

// The layers an image's one encode adds after the film's: `denoised`, when
// a denoiser is given (--denoise; final images only, never checkpoints).
std::vector<exr::PostLayerPlanes> denoised_layer(const std::shared_ptr<denoise::Denoiser>& denoiser,
                                                 const std::shared_ptr<denoise::DenoiseTimes>& times);

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
    MessageSink messages = {};  // where a final image's warning of sums out of range goes

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

    std::vector<exr::PostLayerPlanes> post_layers() const { return denoised_layer(denoiser, denoise_times); }
};

struct FilmOutcome {
    render::StopReason reason = render::StopReason::ReachedSpp;
    bool rendered = false;  // false when stopped before the first pass finished
    render::ProgressState final_state;  // the progress after the last pass
    std::chrono::steady_clock::time_point rendering_began;  // the first pass's start (a start-up's end)
    RunStats stats;         // stats.output is the caller's to fill in
    FinalImage image;       // when rendered; the caller writes it
};

// What rendering one film asks beyond its plan, and whom it tells.
struct FilmRun {
    std::optional<double> time_limit;  // --time SECONDS
    std::optional<double> checkpoint;  // --checkpoint SECONDS: a checkpoint is due this often
    int checkpoint_passes = 0;         // > 0: a checkpoint every this many passes instead (a live preview)
    // The caller's stop flag (orb-render's signal handler sets it), checked
    // between passes: the pass in flight completes. Null: never stopped.
    const std::atomic<bool>* cancel = nullptr;
    // After every pass (orb-render draws its progress line and refreshes its claim).
    std::function<void(const render::ProgressState&)> on_pass;
    // A checkpoint is due: the image so far, for the caller to write. What
    // it throws is said as a warning ("checkpoint not written: ...") and the
    // render goes on (a full disk must not cost the render; the final write
    // reports for good if it persists).
    std::function<void(FinalImage& checkpoint, const render::ProgressState&)> on_checkpoint;
    Film reuse;              // memory for the final image's film (a frame loop hands it back frame after frame)
    // The final image's film is still on its way when render_film returns
    // (FinalImage::wait_for_film), so the renderer can go on to the next frame.
    bool read_later = false;
};

// Renders `plan` to its target on `renderer` (its scene, seed and film set
// up by the caller), handing checkpoints to `run.on_checkpoint`, and
// returns the final image for the caller to write.
FilmOutcome render_film(render::Renderer& renderer, const RenderPlan& plan, FilmRun run);

}  // namespace orb::job
