// Private: the check of the importers' numeric options (*_options.cpp).
// CLI11's PositiveNumber and Range read "nan" and "inf" as doubles and let
// them through, so a meaningless radius or tolerance would reach the reader.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace orb::detail {

// The whole text as a finite number for which `fits` holds; else the message
// "expected <what>, got '<text>'" (a usage error).
CLI::Validator finite_number_check(bool (*fits)(double), const std::string& what);

}  // namespace orb::detail
