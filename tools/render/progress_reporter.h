// Progress on stderr: a single redrawn line when stderr is a terminal; when
// it is not (CI and farm logs), a plain line every `interval` seconds and one
// per checkpoint; nothing under -q. And the line that says what was written.
#pragma once

#include <chrono>
#include <string>

#include "orb/job/film_progress.h"
#include "orb/job/image_output.h"
#include "orb/job/render_film.h"

namespace orb::render_cli {

std::string format_rate(double samples_per_second);  // "1.32 Msamples/s"
std::string format_duration(double seconds);         // "42.0 s", "3 min 05 s"

// "64 spp (samples 64:64) in 2.1 s (1.3 Msamples/s) -> out.exr"
std::string film_summary(const job::FilmOutcome& outcome, const render::Renderer& renderer, const job::ImageOutput& image);

class ProgressReporter final : public job::FilmProgress {
public:
    // `time_limit` 0 means none; it shortens the ETA when it comes first.
    // `interval` is the time between plain lines when stderr is not a terminal.
    ProgressReporter(bool quiet, double time_limit, double interval);

    // `label` starts every line of the film ("frame 12: ").
    void start(const std::string& label, double pixels) override;
    void on_pass(const render::ProgressState& state) override;
    void on_checkpoint(const render::ProgressState& state, const std::string& output) override;
    void finish(const render::ProgressState& final_state) override;  // draws the last state, ends the line

private:
    std::string status_line(const render::ProgressState& state) const;

    bool enabled_;
    bool terminal_;
    double pixels_ = 0;
    double time_limit_;
    std::string label_;
    double interval_;
    bool line_open_ = false;
    std::chrono::steady_clock::time_point last_draw_{};
    std::chrono::steady_clock::time_point last_line_;
};

}  // namespace orb::render_cli
