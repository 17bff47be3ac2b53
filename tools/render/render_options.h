// orb-render's command line: the options as typed, before the scene or a
// resumed file fills in what was left out.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace orb::render_cli {

struct RenderOptions {
    std::string scene;   // path or "-"
    std::string output;  // path or "-"
    bool list_devices = false;
    std::string device;
    std::optional<std::uint64_t> spp;
    std::optional<std::string> sample_range;  // "START:COUNT"
    std::optional<double> time_limit;
    std::optional<double> checkpoint;
    std::string resume;
    std::optional<std::uint64_t> seed;
    std::optional<std::string> mode;
    std::optional<std::string> sampler;
    std::optional<int> max_depth;
    std::optional<int> width;
    std::optional<int> height;
    bool half = false;
    std::optional<std::string> passes;
    std::string stats_json;
    bool benchmark = false;
    double benchmark_seconds = 5.0;
    std::optional<double> time_at;
    std::string kernel_dir;
    bool no_cache = false;
};

void add_render_options(CLI::App& app, RenderOptions& options);

// Combinations CLI11 cannot express; throws orb::cli::UsageError.
void check_option_combinations(const RenderOptions& options);

}  // namespace orb::render_cli
