// Progress on stderr: a single redrawn line when stderr is a terminal; when
// it is not (CI and farm logs), a plain line every `interval` seconds and one
// per checkpoint; nothing under -q.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "orb/render/progressive.h"

namespace orb::render_cli {

std::string format_rate(double samples_per_second);  // "1.32 Msamples/s"
std::string format_duration(double seconds);         // "42.0 s", "3 min 05 s"

class ProgressReporter {
public:
    // `time_limit` 0 means none; it shortens the ETA when it comes first.
    // `label` starts every line ("frame 12: "). `interval` is the time
    // between plain lines when stderr is not a terminal.
    ProgressReporter(bool quiet, double pixels, double time_limit, std::string label = "", double interval = 5.0);

    void on_pass(const render::ProgressState& state);
    void on_checkpoint(const render::ProgressState& state, const std::string& output);
    void finish(const render::ProgressState& final_state);  // draws the last state, ends the line

private:
    std::string status_line(const render::ProgressState& state) const;

    bool enabled_;
    bool terminal_;
    double pixels_;
    double time_limit_;
    std::string label_;
    double interval_;
    bool line_open_ = false;
    std::chrono::steady_clock::time_point last_draw_{};
    std::chrono::steady_clock::time_point last_line_;
};

}  // namespace orb::render_cli
