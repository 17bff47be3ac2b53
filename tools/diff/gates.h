// orb-diff's pass/warn/fail gates.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "orb/image/compare.h"

namespace orb::diff {

// Like idiff, a difference is any channel off by more than 1e-6 unless a
// threshold is given.
constexpr double kDefaultThreshold = 1e-6;

struct GateSet {
    std::optional<double> rmse, relmse, flip, percent, threshold;
};

struct Gates {
    GateSet fail, warn;
    // The "% of pixels over threshold" gates in effect. With no --fail-* gate at
    // all, the fail gate is idiff's: any pixel over the threshold fails.
    bool fail_percent_active() const;
    bool warn_percent_active() const;
    double fail_threshold() const { return fail.threshold.value_or(kDefaultThreshold); }
    double warn_threshold() const { return warn.threshold.value_or(kDefaultThreshold); }
    double fail_percent() const { return fail.percent.value_or(0.0); }
    double warn_percent() const { return warn.percent.value_or(0.0); }
};

enum class Verdict { Pass = 0, Warn = 1, Fail = 2 };
const char* verdict_name(Verdict v);

struct Outcome {
    Verdict verdict = Verdict::Pass;
    std::vector<std::string> failed;  // "rmse 0.02 > 0.01"
    std::vector<std::string> warned;
};

// `comparison.percent_over` holds [fail threshold, warn threshold] in that order.
Outcome judge(const orb::image::PassComparison& comparison, const Gates& gates);

}  // namespace orb::diff
