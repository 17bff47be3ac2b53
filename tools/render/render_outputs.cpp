#include "render_outputs.h"

#include "orb/cli/output_overlap.h"
#include "orb/cli/tool_main.h"

namespace orb::render_cli {

RenderOutputs prepare_render_outputs(const RenderOptions& o) {
    // Frames, and outputs that may be left alone, are prepared one at a time
    // (render_frames.cpp); only --stats-json is prepared here for them.
    // --missing writes nothing.
    const bool image_later = renders_frames(o) || o.skip_existing || o.claim || o.missing;
    std::vector<cli::NamedPath> outputs;
    if (!o.output.empty() && !image_later) outputs.push_back({"-o", o.output});
    if (!o.stats_json.empty()) outputs.push_back({"--stats-json", o.stats_json});
    // Continuing a render in place is the one documented overwrite of an input.
    cli::refuse_overlapping_paths({{"SCENE", o.scene}, {"--resume", o.resume}}, outputs, {{"--resume", "-o"}});

    RenderOutputs prepared;
    if (!o.output.empty() && !image_later) {
        prepared.image.emplace(o.output, "-o");
        if (o.checkpoint && prepared.image->kind() == cli::OutputFile::Kind::Stream)
            throw cli::UsageError("--checkpoint rewrites the output while rendering, but -o " + o.output + " is " +
                                  prepared.image->stream_description() + "; drop --checkpoint");
    }
    if (!o.stats_json.empty()) prepared.stats.emplace(o.stats_json, "--stats-json");
    return prepared;
}

}  // namespace orb::render_cli
