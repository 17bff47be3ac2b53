// orb-render's outputs, checked against its inputs and prepared (locked,
// temporary files created) before the scene is read or a pass is rendered,
// so that a render which cannot be written fails in its first second.
#pragma once

#include <optional>
#include <string>

#include "orb/cli/output_file.h"
#include "orb/job/image_output.h"
#include "render_options.h"

namespace orb::render_cli {

struct RenderOutputs {
    std::optional<cli::OutputFile> image;  // -o; none for --benchmark, nor for the frame loop's outputs
    std::optional<cli::OutputFile> stats;  // --stats-json
};

// Throws orb::cli::UsageError for an output that is an input (except the
// documented --resume X -o X) or another output, or --checkpoint into a
// device or FIFO; orb::InputError for an output that cannot be written.
RenderOutputs prepare_render_outputs(const RenderOptions& options);

// The image output at `path` (-o, or a frame's name from it), locked and
// ready; throws as prepare_render_outputs does for --checkpoint into a
// device or FIFO.
cli::OutputFile open_image_output(const std::string& path, const RenderOptions& options);

// An output of orb-render as the render job writes it.
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

}  // namespace orb::render_cli
