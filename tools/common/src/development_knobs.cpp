#include "orb/cli/development_knobs.h"

#include <cmath>
#include <cstdlib>
#include <optional>

#include "orb/cli/messages.h"
#include "orb/cli/tool_main.h"

namespace orb::cli {
namespace {

// The variable's value, or nothing when it is unset or empty (a script's
// ORB_SIMD_LANES=${LANES:-} leaves the default).
std::optional<std::string> value_of(const EnvironmentLookup& lookup, const char* name)
{
    const char* value = lookup(name);
    if (!value || !*value) return std::nullopt;
    return std::string(value);
}

[[noreturn]] void malformed(const char* name, const std::string& value, const std::string& expected)
{
    throw UsageError(std::string("development knob ") + name + "='" + value + "': expected " + expected);
}

// The whole text as a non-negative decimal integer, or nothing.
std::optional<unsigned long> parse_count(const std::string& text)
{
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    if (text.size() > 9) return std::nullopt;  // far past any sensible lane count or work-group side
    return std::stoul(text);
}

int parse_simd_lanes(const std::string& text)
{
    const std::optional<unsigned long> lanes = parse_count(text);
    if (!lanes || (*lanes != 0 && *lanes != 4 && *lanes != 8 && *lanes != 16))
        malformed("ORB_SIMD_LANES", text, "0 (one path per work-item), 4, 8 or 16 (lanes)");
    return static_cast<int>(*lanes);
}

int parse_pass_spp(const std::string& text)
{
    const std::optional<unsigned long> spp = parse_count(text);
    if (!spp || *spp == 0 || *spp > 4096) malformed("ORB_PASS_SPP", text, "a whole number of samples from 1 to 4096");
    return static_cast<int>(*spp);
}

render::LocalSize parse_local_size(const std::string& text)
{
    const std::size_t cross = text.find('x');
    const std::optional<unsigned long> x = parse_count(text.substr(0, cross));
    const std::optional<unsigned long> y =
        cross == std::string::npos ? std::nullopt : parse_count(text.substr(cross + 1));
    if (!x || !y || *x == 0 || *y == 0)
        malformed("ORB_LOCAL_SIZE", text, "a work-group shape XxY of two positive integers, e.g. 16x8");
    return {static_cast<unsigned>(*x), static_cast<unsigned>(*y)};
}

double parse_refit_cost_limit(const std::string& text)
{
    try {
        std::size_t used = 0;
        const double limit = std::stod(text, &used);
        if (used == text.size() && std::isfinite(limit) && limit >= 0) return limit;
    } catch (const std::exception&) {
    }
    malformed("ORB_REFIT_COST_LIMIT", text, "a finite number >= 0 (a multiple of the built tree's SAH cost; 0: never refit)");
}

bool parse_switch(const char* name, const std::string& text)
{
    if (text == "1") return true;
    if (text == "0") return false;
    malformed(name, text, "1 (on) or 0 (off)");
}

}  // namespace

render::DevelopmentKnobs parse_development_knobs(const EnvironmentLookup& lookup, std::vector<std::string>& warnings)
{
    render::DevelopmentKnobs knobs;
    if (auto dir = value_of(lookup, "ORB_KERNEL_DIR")) knobs.kernel_dir = *dir;
    if (auto options = value_of(lookup, "ORB_CL_OPTIONS")) knobs.cl_options = *options;
    if (auto lanes = value_of(lookup, "ORB_SIMD_LANES")) knobs.simd_lanes = parse_simd_lanes(*lanes);
    if (auto size = value_of(lookup, "ORB_LOCAL_SIZE")) knobs.local_size = parse_local_size(*size);
    if (auto spp = value_of(lookup, "ORB_PASS_SPP")) knobs.pass_spp = parse_pass_spp(*spp);
    if (auto limit = value_of(lookup, "ORB_REFIT_COST_LIMIT")) knobs.refit_cost_limit = parse_refit_cost_limit(*limit);
    if (auto log = value_of(lookup, "ORB_SHOW_BUILD_LOG")) knobs.show_build_log = parse_switch("ORB_SHOW_BUILD_LOG", *log);
    if (auto decisions = value_of(lookup, "ORB_DEVICE_DECISIONS"))
        knobs.device_decisions = parse_switch("ORB_DEVICE_DECISIONS", *decisions);
    for (const char* moved : {"ORB_CAPTURE_PASS", "ORB_CAPTURE_SKIP"})
        if (value_of(lookup, moved))
            warnings.push_back(std::string(moved) +
                               " is set but ignored: the pass capture is a development tool, orb-capture-pass, "
                               "built with -DORB_BUILD_DEV=ON (dev/README.md)");
    return knobs;
}

render::DevelopmentKnobs development_knobs_from_environment()
{
    std::vector<std::string> warnings;
    render::DevelopmentKnobs knobs =
        parse_development_knobs([](const char* name) { return std::getenv(name); }, warnings);
    for (const std::string& line : warnings) warning(line);
    return knobs;
}

}  // namespace orb::cli
