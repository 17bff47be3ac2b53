// orb-render's side of rendering one film (orb/job/render_film.h): the
// progress lines, checkpoints written to its output, a farm claim kept
// fresh, and the line that says what was written.
#pragma once

#include <string>

#include "orb/cli/output_file.h"
#include "orb/job/frame_claim.h"
#include "orb/job/image_output.h"
#include "orb/job/render_film.h"
#include "render_options.h"

namespace orb::render_cli {

// An output of orb-render as the render job writes it (the background writer's frames).
class OutputFileImage final : public job::ImageOutput {
public:
    explicit OutputFileImage(cli::OutputFile file) : file_(std::move(file)) {}
    void stage(std::string_view bytes) override { file_.stage(bytes); }
    void commit(std::string_view bytes) override { file_.commit(bytes); }
    std::string display_name() const override { return file_.display_name(); }
    std::string path() const override { return file_.path(); }

private:
    cli::OutputFile file_;
};

// Renders `plan` on `renderer` (job::render_film), stopped by SIGINT or
// SIGTERM, writing checkpoints to `image`; `label` starts the progress
// lines, and a `claim` is refreshed while rendering. The final image is the
// caller's to write (its film still on its way with `read_later`).
job::FilmOutcome render_film(render::Renderer& renderer, const job::RenderPlan& plan, const RenderOptions& options,
                             job::ImageOutput& image, const std::string& label, job::FrameClaim* claim,
                             Film reuse = {}, bool read_later = false);

// "64 spp (samples 64:64) in 2.1 s (1.3 Msamples/s) -> out.exr"
std::string film_summary(const job::FilmOutcome& outcome, const render::Renderer& renderer, const job::ImageOutput& image);

}  // namespace orb::render_cli
