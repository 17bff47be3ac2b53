// orb-render's outputs, checked against its inputs and prepared (locked,
// temporary files created) before the scene is read or a pass is rendered,
// so that a render which cannot be written fails in its first second.
#pragma once

#include <optional>
#include <string>

#include "orb/cli/output_file.h"
#include "orb/cli/output_file_image.h"
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

using cli::OutputFileImage;  // an output of orb-render as the render job writes it

}  // namespace orb::render_cli
