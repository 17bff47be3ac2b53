// Validators for numeric options. CLI11 reads "nan" and "inf" as doubles and
// its Range lets NaN through, so without these a meaningless value would run
// (and, say, a NaN gate would pass everything).
#pragma once

#include <functional>
#include <initializer_list>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace orb::cli {

// The whole text as a number, or nothing: "1.5x", "" and " 1.5" are not
// numbers here (std::stod alone would read a prefix and skip leading spaces).
std::optional<double> parse_number(const std::string& text);

// A finite number for which `fits` holds; the message reads "expected <what>, got '<text>'".
CLI::Validator finite_number_where(std::function<bool(double)> fits, const std::string& what);

// A finite number in [lo, hi], with the same message.
CLI::Validator finite_number_in(double lo, double hi, const std::string& what);

// One of a few whole numbers, written plainly ("12" is refused for {8, 16, 32}).
CLI::Validator one_of(std::initializer_list<int> allowed);

}  // namespace orb::cli
