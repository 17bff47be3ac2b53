#include "gates.h"

#include <cstdio>

namespace orb::diff {
namespace {

std::string describe(const char* metric, double value, double limit, const char* unit = "") {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "%s %.6g%s > %.6g%s", metric, value, unit, limit, unit);
    return buffer;
}

// Checks one gate set, appending the gates that trip to `tripped`.
void check(const orb::image::PassComparison& c, const GateSet& gates, bool percent_active, double percent_limit,
           double percent_value, std::vector<std::string>& tripped) {
    if (gates.rmse && c.stats.rmse > *gates.rmse) tripped.push_back(describe("rmse", c.stats.rmse, *gates.rmse));
    if (gates.relmse && c.stats.relmse > *gates.relmse)
        tripped.push_back(describe("relmse", c.stats.relmse, *gates.relmse));
    if (gates.flip && c.flip && c.flip->mean > *gates.flip)
        tripped.push_back(describe("flip", c.flip->mean, *gates.flip));
    if (percent_active && percent_value > percent_limit)
        tripped.push_back(describe("pixels over threshold", percent_value, percent_limit, "%"));
}

}  // namespace

std::string describe_tolerance(orb::image::Tolerance tolerance) {
    char buffer[96];
    if (tolerance.relative == 0)
        std::snprintf(buffer, sizeof buffer, "%.3g", tolerance.absolute);
    else
        std::snprintf(buffer, sizeof buffer, "%.3g + %.3g*max(|a|,|b|)", tolerance.absolute, tolerance.relative);
    return buffer;
}

bool Gates::fail_percent_active() const {
    const bool any_fail_gate = fail.rmse || fail.relmse || fail.flip || fail.percent || fail.threshold;
    return fail.percent || fail.threshold || !any_fail_gate;
}

bool Gates::warn_percent_active() const { return warn.percent || warn.threshold; }

const char* verdict_name(Verdict v) {
    switch (v) {
        case Verdict::Pass: return "pass";
        case Verdict::Warn: return "warn";
        case Verdict::Fail: return "fail";
    }
    return "fail";
}

Outcome judge(const orb::image::PassComparison& c, const Gates& gates) {
    Outcome o;
    check(c, gates.fail, gates.fail_percent_active(), gates.fail_percent(), c.percent_over.at(0), o.failed);
    check(c, gates.warn, gates.warn_percent_active(), gates.warn_percent(), c.percent_over.at(1), o.warned);
    o.verdict = !o.failed.empty() ? Verdict::Fail : !o.warned.empty() ? Verdict::Warn : Verdict::Pass;
    return o;
}

}  // namespace orb::diff
