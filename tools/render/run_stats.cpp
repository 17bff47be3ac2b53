#include "run_stats.h"

#include <nlohmann/json.hpp>

namespace orb::render_cli {

namespace {

nlohmann::ordered_json to_json(const RunStats& s) {
    nlohmann::ordered_json device{{"index", s.device.index},
                                  {"name", s.device.name},
                                  {"platform", s.device.platform},
                                  {"type", s.device.is_gpu ? "gpu" : s.device.is_cpu ? "cpu" : "other"},
                                  {"compute_units", s.device.compute_units},
                                  {"global_memory_bytes", s.device.global_memory_bytes}};
    nlohmann::ordered_json j{{"device", device},
                             {"width", s.width},
                             {"height", s.height},
                             {"spp", s.spp},
                             {"spp_this_run", s.spp_this_run},
                             {"sample_ranges", s.sample_ranges},
                             {"passes", s.passes},
                             {"seconds", s.seconds},
                             {"samples_per_second", s.samples_per_second},
                             {"device_memory_bytes", s.device_memory_bytes},
                             {"stop_reason", s.stop_reason},
                             {"output", s.output}};
    if (s.frame) j["frame"] = *s.frame;
    return j;
}

}  // namespace

std::string stats_json(const RunStats& s) { return to_json(s).dump(2) + "\n"; }

std::string frames_stats_json(const std::vector<RunStats>& frames, const std::vector<long>& skipped) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const RunStats& frame : frames) list.push_back(to_json(frame));
    nlohmann::ordered_json j{{"frames", list}, {"skipped", skipped}};
    return j.dump(2) + "\n";
}

}  // namespace orb::render_cli
