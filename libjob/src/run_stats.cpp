#include "orb/job/run_stats.h"

#include <nlohmann/json.hpp>

namespace orb::job {

namespace {

nlohmann::ordered_json device_json(const render::DeviceInfo& d) {
    return {{"index", d.index},
            {"name", d.name},
            {"platform", d.platform},
            {"type", d.is_gpu ? "gpu" : d.is_cpu ? "cpu" : "other"},
            {"compute_units", d.compute_units},
            {"global_memory_bytes", d.global_memory_bytes}};
}

nlohmann::ordered_json to_json(const RunStats& s) {
    nlohmann::ordered_json devices = nlohmann::ordered_json::array();
    for (const DeviceShare& share : s.devices) {
        nlohmann::ordered_json entry = device_json(share.device);
        entry["spp"] = share.spp;
        devices.push_back(entry);
    }
    nlohmann::ordered_json j{{"device", device_json(s.device)},
                             {"devices", devices},
                             {"width", s.width},
                             {"height", s.height},
                             {"spp", s.spp},
                             {"spp_this_run", s.spp_this_run},
                             {"samples", s.samples},
                             {"samples_this_run", s.samples_this_run},
                             {"sample_ranges", s.sample_ranges},
                             {"passes", s.passes},
                             {"seconds", s.seconds},
                             {"samples_per_second", s.samples_per_second},
                             {"device_memory_bytes", s.device_memory_bytes},
                             {"bvh_nodes", s.bvh_nodes},
                             {"bvh_seconds", s.bvh_seconds},
                             {"stop_reason", s.stop_reason},
                             {"output", s.output}};
    if (s.setup_seconds) j["setup_seconds"] = *s.setup_seconds;
    j["kernel_build_seconds"] = s.kernel_build_seconds;
    if (s.startup_seconds) j["startup_seconds"] = *s.startup_seconds;
    if (s.estimated_relmse) j["estimated_relmse"] = *s.estimated_relmse;
    if (s.active_pixels) j["active_pixels"] = *s.active_pixels;
    if (s.decisions) j["decisions"] = *s.decisions;
    if (s.decision_seconds) j["decision_seconds"] = *s.decision_seconds;
    if (s.denoise) {
        j["denoise_seconds"] = s.denoise->seconds;
        j["denoise_setup_seconds"] = s.denoise->setup_seconds;
        j["denoise_filter_seconds"] = s.denoise->filter_seconds;
    }
    if (s.frame) j["frame"] = *s.frame;
    return j;
}

}  // namespace

RunStats renderer_stats(const render::Renderer& renderer) {
    RunStats stats;
    stats.device = renderer.device();
    for (std::size_t d = 0; d < renderer.devices().size(); ++d)
        stats.devices.push_back({renderer.devices()[d], renderer.device_sample_ranges()[d].total()});
    stats.width = renderer.config().width;
    stats.height = renderer.config().height;
    stats.device_memory_bytes = renderer.device_memory_bytes();
    const render::Renderer::TreeReport tree = renderer.tree_report();
    stats.bvh_nodes = tree.nodes;
    stats.bvh_seconds = tree.seconds;
    stats.spp = renderer.samples_per_pixel();
    stats.samples = renderer.pixel_samples();
    stats.kernel_build_seconds = renderer.kernel_build_seconds();
    return stats;
}

std::string stats_json(const RunStats& s) { return to_json(s).dump(2) + "\n"; }

std::string frames_stats_json(const std::vector<RunStats>& frames, const std::vector<long>& skipped) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const RunStats& frame : frames) list.push_back(to_json(frame));
    nlohmann::ordered_json j{{"frames", list}, {"skipped", skipped}};
    return j.dump(2) + "\n";
}

}  // namespace orb::job
