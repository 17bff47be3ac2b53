#include "run_stats.h"

#include <nlohmann/json.hpp>

namespace orb::render_cli {

std::string stats_json(const RunStats& s) {
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
    return j.dump(2) + "\n";
}

}  // namespace orb::render_cli
