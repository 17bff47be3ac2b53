// Validators for numeric options. CLI11 reads "nan" and "inf" as doubles and
// its Range lets NaN through, so without these a meaningless value would run
// (and, say, a NaN gate would pass everything).
#pragma once

#include <initializer_list>
#include <string>

#include <CLI/CLI.hpp>

namespace orb::cli {

// A finite number in [lo, hi]; the message reads "expected <what>, got '<text>'".
CLI::Validator finite_number_in(double lo, double hi, const std::string& what);

// One of a few whole numbers, written plainly ("12" is refused for {8, 16, 32}).
CLI::Validator one_of(std::initializer_list<int> allowed);

}  // namespace orb::cli
