#include "option_checks.h"

#include <charconv>
#include <cmath>

namespace orb::detail {

CLI::Validator finite_number_check(bool (*fits)(double), const std::string& what) {
    const auto check = [fits, what](std::string& text) -> std::string {
        double value = 0;
        const char* end = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), end, value);
        const bool number = !text.empty() && error == std::errc() && stop == end;
        return number && std::isfinite(value) && fits(value) ? std::string() : "expected " + what + ", got '" + text + "'";
    };
    return CLI::Validator(check, "NUMBER");
}

}  // namespace orb::detail
