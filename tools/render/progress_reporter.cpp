#include "progress_reporter.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "orb/cli/messages.h"

namespace orb::render_cli {

std::string format_rate(double samples_per_second) {
    const char* units[] = {"", "k", "M", "G", "T"};
    int unit = 0;
    double value = samples_per_second;
    while (value >= 1000.0 && unit < 4) {
        value /= 1000.0;
        ++unit;
    }
    char text[64];
    std::snprintf(text, sizeof text, "%.3g %ssamples/s", value, units[unit]);
    return text;
}

std::string format_duration(double seconds) {
    char text[64];
    if (!std::isfinite(seconds) || seconds < 0) return "?";
    if (seconds < 10)  // short GPU renders: keep two digits
        std::snprintf(text, sizeof text, "%.2g s", seconds);
    else if (seconds < 60)
        std::snprintf(text, sizeof text, "%.1f s", seconds);
    else if (seconds < 3600)
        std::snprintf(text, sizeof text, "%d min %02d s", int(seconds) / 60, int(seconds) % 60);
    else
        std::snprintf(text, sizeof text, "%d h %02d min", int(seconds) / 3600, int(seconds) / 60 % 60);
    return text;
}

std::string film_summary(const job::FilmOutcome& outcome, const render::Renderer& renderer, const job::ImageOutput& image) {
    const SampleRanges& held = renderer.sample_ranges();
    return std::to_string(outcome.stats.spp) + " spp" +
           (job::holds_samples_from_zero(held) ? "" : " (samples " + held.format() + ")") + " in " +
           format_duration(outcome.stats.seconds) + " (" + format_rate(outcome.stats.samples_per_second) + ") -> " +
           image.display_name();
}

ProgressReporter::ProgressReporter(bool quiet, double time_limit, double interval)
    : enabled_(!quiet),
      terminal_(::isatty(STDERR_FILENO) == 1),
      time_limit_(time_limit),
      interval_(interval),
      last_line_(std::chrono::steady_clock::now()) {}

void ProgressReporter::start(const std::string& label, double pixels) {
    label_ = label;
    pixels_ = pixels;
    last_line_ = std::chrono::steady_clock::now();  // a log's first line of the film comes `interval` after its start
}

std::string ProgressReporter::status_line(const render::ProgressState& s) const {
    const job::ProgressEstimate estimate = job::estimate_progress(s, pixels_, time_limit_);
    char text[256];
    std::snprintf(text, sizeof text, "%spass %d  %llu/%llu spp (%3.0f%%)  %s  elapsed %s  ETA %s", label_.c_str(),
                  s.pass,
                  static_cast<unsigned long long>(s.spp), static_cast<unsigned long long>(s.target_spp),
                  100.0 * estimate.fraction, format_rate(s.samples_per_second).c_str(),
                  format_duration(s.elapsed_seconds).c_str(), format_duration(estimate.eta_seconds).c_str());
    return text;
}

void ProgressReporter::on_pass(const render::ProgressState& state) {
    if (!enabled_) return;
    if (!terminal_) {
        // A log gets a plain line now and then, so it shows the render is alive.
        const auto now = std::chrono::steady_clock::now();
        if (std::chrono::duration<double>(now - last_line_).count() < interval_) return;
        last_line_ = now;
        cli::info(status_line(state));
        return;
    }
    // Redraw at most ~10 times a second: short GPU passes come far faster.
    const auto now = std::chrono::steady_clock::now();
    if (line_open_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    std::cerr << "\r\033[K" << status_line(state) << std::flush;
    line_open_ = true;
}

void ProgressReporter::on_checkpoint(const render::ProgressState& state, const std::string& output) {
    if (!enabled_ || terminal_) return;
    last_line_ = std::chrono::steady_clock::now();
    cli::info("checkpoint " + output + ": " + status_line(state));
}

void ProgressReporter::finish(const render::ProgressState& final_state) {
    if (line_open_) std::cerr << "\r\033[K" << status_line(final_state) << "\n" << std::flush;
    line_open_ = false;
}

}  // namespace orb::render_cli
