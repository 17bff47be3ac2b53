#include "report.h"

#include <cmath>
#include <cstdio>

namespace orb::diff {
namespace {

// JSON has no infinities: an identical pair's PSNR is reported as null.
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json gate_set_json(const GateSet& g, bool percent_active, double percent, orb::image::Tolerance tolerance) {
    auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
    return {{"rmse", opt(g.rmse)},
            {"relmse", opt(g.relmse)},
            {"flip", opt(g.flip)},
            {"percent", percent_active ? nlohmann::json(percent) : nlohmann::json(nullptr)},
            {"threshold", tolerance.absolute},
            {"relative_threshold", tolerance.relative}};
}

}  // namespace

std::string summary_line(const PassResult& r, const Gates& gates) {
    const auto& c = r.comparison;
    const auto& s = c.stats;
    char buffer[512];
    std::snprintf(buffer, sizeof buffer,
                  "%s [%s]: mean abs %.6g, max abs %.6g at (%d, %d) %s, RMSE %.6g, PSNR %.2f dB, relMSE %.6g, "
                  "%.4g%% of pixels over %s",
                  c.pass.c_str(), c.space.c_str(), s.mean_abs_error, s.max_abs_error, s.max_x, s.max_y,
                  s.max_channel.c_str(), s.rmse, s.psnr, s.relmse, c.percent_over.at(0),
                  describe_tolerance(gates.fail_tolerance()).c_str());
    std::string line = buffer;
    if (c.flip) {
        std::snprintf(buffer, sizeof buffer, ", %s %.6f", c.flip->hdr ? "HDR-FLIP" : "LDR-FLIP", c.flip->mean);
        line += buffer;
    }
    line += std::string(" -> ") + verdict_name(r.outcome.verdict);
    for (const auto& f : r.outcome.failed) line += "\n  fail: " + f;
    for (const auto& w : r.outcome.warned) line += "\n  warn: " + w;
    return line;
}

nlohmann::json pass_json(const PassResult& r, const Gates& gates) {
    const auto& c = r.comparison;
    const auto& s = c.stats;
    nlohmann::json metrics = {
        {"mean_abs_error", number(s.mean_abs_error)},
        {"max_abs_error",
         {{"value", number(s.max_abs_error)}, {"x", s.max_x}, {"y", s.max_y}, {"channel", s.max_channel}}},
        {"rmse", number(s.rmse)},
        {"psnr", number(s.psnr)},
        {"relmse", number(s.relmse)},
        {"relmse_epsilon", orb::image::kRelMseEpsilon},
        {"nonfinite_differences", s.nonfinite},
        {"percent_over_fail_threshold", c.percent_over.at(0)},
        {"percent_over_warn_threshold", c.percent_over.at(1)},
    };
    if (c.flip) {
        nlohmann::json flip = {{"variant", c.flip->hdr ? "HDR-FLIP" : "LDR-FLIP"},
                               {"mean", c.flip->mean},
                               {"max", c.flip->max}};
        if (c.flip->hdr)
            flip["exposures"] = {{"start", c.flip->start_exposure},
                                 {"stop", c.flip->stop_exposure},
                                 {"count", c.flip->exposures}};
        metrics["flip"] = flip;
    } else {
        metrics["flip"] = nullptr;
    }
    (void)gates;
    return {{"pass", c.pass},
            {"kind", orb::image::kind_name(c.kind)},
            {"space", c.space},
            {"width", c.width},
            {"height", c.height},
            {"channels", c.channels},
            {"metrics", metrics},
            {"verdict", verdict_name(r.outcome.verdict)},
            {"failed", r.outcome.failed},
            {"warned", r.outcome.warned}};
}

nlohmann::json gates_json(const Gates& g) {
    return {{"fail", gate_set_json(g.fail, g.fail_percent_active(), g.fail_percent(), g.fail_tolerance())},
            {"warn", gate_set_json(g.warn, g.warn_percent_active(), g.warn_percent(), g.warn_tolerance())}};
}

}  // namespace orb::diff
