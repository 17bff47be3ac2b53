// --stats-json: the figures of one run, for farms and CI dashboards.
#pragma once

#include <cstdint>
#include <string>

#include "orb/render/device.h"

namespace orb::render_cli {

struct RunStats {
    render::DeviceInfo device;
    int width = 0;
    int height = 0;
    std::uint64_t spp = 0;           // samples per pixel in the image, resumed ones included
    std::uint64_t spp_this_run = 0;  // samples per pixel this run added
    int passes = 0;
    double seconds = 0;              // this run's rendering (or timed benchmark) time
    double samples_per_second = 0;   // pixel samples per second over `seconds`
    std::uint64_t device_memory_bytes = 0;
    std::string stop_reason;         // "spp", "time", "interrupted" or "benchmark"
    std::string output;              // "" for --benchmark
    std::string sample_ranges;       // the sample indices in the image, "0:64"; "" for --benchmark
};

std::string stats_json(const RunStats& stats);

}  // namespace orb::render_cli
