// orb-diff's pass/warn/fail gates.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "orb/image/compare.h"

namespace orb::diff {

// Without --*-threshold, a channel differs when it is off by more than float
// rounding can explain: |a - b| > 1e-6 + 1e-4 * max(|a|, |b|). Renders that
// add the same samples in another order (a resumed render, another device)
// agree within about 1e-5 relative (float's epsilon, 1.2e-7, times the
// additions a pixel's sum goes through); 1e-4 leaves ten times that margin
// and is still far below what can be seen (an 8-bit step is 4e-3 of white).
// The absolute 1e-6 (idiff's default) covers values near zero, where a
// relative bound means nothing.
constexpr orb::image::Tolerance kDefaultTolerance{1e-6, 1e-4};

struct GateSet {
    std::optional<double> rmse, relmse, flip, percent, threshold;
};

struct Gates {
    GateSet fail, warn;
    // The "% of pixels over threshold" gates in effect. With no --fail-* gate at
    // all, the fail gate is idiff's: any pixel over the threshold fails.
    bool fail_percent_active() const;
    bool warn_percent_active() const;
    // An explicit threshold T is absolute: |a - b| > T.
    orb::image::Tolerance fail_tolerance() const { return tolerance(fail); }
    orb::image::Tolerance warn_tolerance() const { return tolerance(warn); }
    double fail_percent() const { return fail.percent.value_or(0.0); }
    double warn_percent() const { return warn.percent.value_or(0.0); }

private:
    static orb::image::Tolerance tolerance(const GateSet& g) {
        return g.threshold ? orb::image::Tolerance{*g.threshold, 0.0} : kDefaultTolerance;
    }
};

// "0.02", or "1e-06 + 0.0001*max(|a|,|b|)" for a relative tolerance.
std::string describe_tolerance(orb::image::Tolerance tolerance);

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
