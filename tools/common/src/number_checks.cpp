#include "orb/cli/number_checks.h"

#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace orb::cli {

std::optional<double> parse_number(const std::string& text) {
    if (text.empty() || text.front() == ' ') return std::nullopt;
    try {
        std::size_t used = 0;
        const double value = std::stod(text, &used);
        if (used == text.size()) return value;
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

CLI::Validator finite_number_where(std::function<bool(double)> fits, const std::string& what) {
    return CLI::Validator(
        [fits, what](std::string& text) -> std::string {
            const std::optional<double> value = parse_number(text);
            if (value && std::isfinite(*value) && fits(*value)) return {};
            return "expected " + what + ", got '" + text + "'";
        },
        "NUMBER");
}

CLI::Validator finite_number_in(double lo, double hi, const std::string& what) {
    return finite_number_where([lo, hi](double value) { return value >= lo && value <= hi; }, what);
}

CLI::Validator one_of(std::initializer_list<int> allowed) {
    const std::vector<int> values(allowed);
    std::string list;
    for (std::size_t i = 0; i < values.size(); ++i)
        list += (i == 0 ? "" : i + 1 == values.size() ? " or " : ", ") + std::to_string(values[i]);
    return CLI::Validator(
        [values, list](std::string& text) -> std::string {
            int value = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (error == std::errc{} && end == text.data() + text.size())
                for (int v : values)
                    if (v == value) return {};
            return "expected " + list + ", got '" + text + "'";
        },
        list);
}

}  // namespace orb::cli
