// Diff-friendly JSON text: one key per line at the top level, each element of
// an array of objects on a line of its own, flat objects and number arrays on
// one line, and numbers in the shortest form that reads back exactly.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace orb::detail {

std::string format_json(const nlohmann::ordered_json& value);

// Shortest decimal text that reads back to exactly `value` ("50", "0.75",
// "100000", "5e-324"): plain notation for ordinary magnitudes, exponent
// notation for very large or small ones.
std::string format_number(double value);
// The same text, appended to `out` (no string per number: the writers of a
// million spheres call it four times per sphere).
void append_number(std::string& out, double value);

}  // namespace orb::detail
