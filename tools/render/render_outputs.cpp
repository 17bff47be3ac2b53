#include "render_outputs.h"

#include "orb/cli/output_overlap.h"
#include "orb/cli/tool_main.h"

namespace orb::render_cli {

RenderOutputs prepare_render_outputs(const RenderOptions& o) {
    // The frame loop's outputs are prepared one at a time (render_frames.cpp);
    // only --stats-json is prepared here for them. --missing writes nothing.
    const bool image_now = !o.output.empty() && !runs_frame_loop(o);
    std::vector<cli::NamedPath> outputs;
    if (image_now) outputs.push_back({"-o", o.output});
    if (!o.stats_json.empty()) outputs.push_back({"--stats-json", o.stats_json});
    // Continuing a render in place is the one documented overwrite of an input.
    cli::refuse_overlapping_paths({{"SCENE", o.scene}, {"--resume", o.resume}}, outputs, {{"--resume", "-o"}});

    RenderOutputs prepared;
    if (image_now) prepared.image.emplace(open_image_output(o.output, o));
    if (!o.stats_json.empty()) prepared.stats.emplace(o.stats_json, "--stats-json");
    return prepared;
}

cli::OutputFile open_image_output(const std::string& path, const RenderOptions& options) {
    cli::OutputFile image(path, "-o");
    if (options.checkpoint && image.kind() == cli::OutputFile::Kind::Stream)
        throw cli::UsageError("--checkpoint rewrites the output while rendering, but -o " + path + " is " +
                              image.stream_description() + "; drop --checkpoint");
    return image;
}

}  // namespace orb::render_cli
