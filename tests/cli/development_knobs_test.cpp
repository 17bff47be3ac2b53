// The development knobs as the tools read them from the environment
// (tools/common, orb/cli/development_knobs.h): each variable's good values,
// and a malformed one refused with its name, its value and what was expected.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "orb/cli/development_knobs.h"
#include "orb/cli/tool_main.h"

using orb::cli::parse_development_knobs;
using orb::render::DevelopmentKnobs;

namespace {

DevelopmentKnobs parse(const std::map<std::string, std::string>& environment,
                       std::vector<std::string>* warnings_out = nullptr)
{
    std::vector<std::string> warnings;
    DevelopmentKnobs knobs = parse_development_knobs(
        [&](const char* name) -> const char* {
            const auto found = environment.find(name);
            return found == environment.end() ? nullptr : found->second.c_str();
        },
        warnings);
    if (warnings_out) *warnings_out = warnings;
    return knobs;
}

// The message of the UsageError that parsing `environment` throws ("" if none).
std::string refusal(const std::map<std::string, std::string>& environment)
{
    try {
        parse(environment);
    } catch (const orb::cli::UsageError& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST(DevelopmentKnobsParser, NothingSetIsTheDefaults)
{
    std::vector<std::string> warnings;
    const DevelopmentKnobs knobs = parse({}, &warnings);
    EXPECT_EQ(knobs.kernel_dir, "");
    EXPECT_EQ(knobs.cl_options, "");
    EXPECT_FALSE(knobs.simd_lanes);
    EXPECT_FALSE(knobs.local_size);
    EXPECT_FALSE(knobs.refit_cost_limit);
    EXPECT_FALSE(knobs.pass_spp);
    EXPECT_FALSE(knobs.show_build_log);
    EXPECT_FALSE(knobs.pass_observer);
    EXPECT_TRUE(warnings.empty());
}

TEST(DevelopmentKnobsParser, ReadsEveryKnob)
{
    const DevelopmentKnobs knobs = parse({{"ORB_KERNEL_DIR", "/tmp/kernels"},
                                          {"ORB_CL_OPTIONS", "-DORB_SCALAR_TRAVERSAL=1 -cl-nv-verbose"},
                                          {"ORB_SIMD_LANES", "8"},
                                          {"ORB_LOCAL_SIZE", "32x4"},
                                          {"ORB_PASS_SPP", "7"},
                                          {"ORB_REFIT_COST_LIMIT", "1.5"},
                                          {"ORB_SHOW_BUILD_LOG", "1"},
                                          {"ORB_DEVICE_DECISIONS", "1"}});
    EXPECT_EQ(knobs.kernel_dir, "/tmp/kernels");
    EXPECT_EQ(knobs.cl_options, "-DORB_SCALAR_TRAVERSAL=1 -cl-nv-verbose");
    EXPECT_EQ(knobs.simd_lanes, 8);
    EXPECT_EQ(knobs.local_size, (orb::render::LocalSize{32, 4}));
    EXPECT_EQ(knobs.pass_spp, 7);
    EXPECT_EQ(knobs.refit_cost_limit, 1.5);
    EXPECT_TRUE(knobs.show_build_log);
    EXPECT_EQ(knobs.device_decisions, true);
}

TEST(DevelopmentKnobsParser, EveryLaneCountAndOff)
{
    for (int lanes : {0, 4, 8, 16}) EXPECT_EQ(parse({{"ORB_SIMD_LANES", std::to_string(lanes)}}).simd_lanes, lanes);
    EXPECT_EQ(parse({{"ORB_REFIT_COST_LIMIT", "0"}}).refit_cost_limit, 0.0);
    EXPECT_FALSE(parse({{"ORB_SHOW_BUILD_LOG", "0"}}).show_build_log);
    EXPECT_EQ(parse({{"ORB_DEVICE_DECISIONS", "0"}}).device_decisions, false);
    EXPECT_FALSE(parse({}).device_decisions);  // unset: the renderer's default
}

TEST(DevelopmentKnobsParser, AnEmptyValueIsUnset)
{
    const DevelopmentKnobs knobs =
        parse({{"ORB_SIMD_LANES", ""}, {"ORB_LOCAL_SIZE", ""}, {"ORB_REFIT_COST_LIMIT", ""}, {"ORB_SHOW_BUILD_LOG", ""}});
    EXPECT_FALSE(knobs.simd_lanes);
    EXPECT_FALSE(knobs.local_size);
    EXPECT_FALSE(knobs.refit_cost_limit);
    EXPECT_FALSE(knobs.show_build_log);
}

TEST(DevelopmentKnobsParser, AMalformedValueNamesTheVariableAndWhatWasExpected)
{
    const std::string local = refusal({{"ORB_LOCAL_SIZE", "abc"}});
    EXPECT_NE(local.find("ORB_LOCAL_SIZE='abc'"), std::string::npos) << local;
    EXPECT_NE(local.find("expected a work-group shape XxY"), std::string::npos) << local;
    for (const char* bad : {"16", "16x", "x8", "0x8", "16x0", "16x8x2", "-4x2", "16 x 8", "99999999999x1"})
        EXPECT_NE(refusal({{"ORB_LOCAL_SIZE", bad}}), "") << bad;

    const std::string lanes = refusal({{"ORB_SIMD_LANES", "6"}});
    EXPECT_NE(lanes.find("ORB_SIMD_LANES='6'"), std::string::npos) << lanes;
    EXPECT_NE(lanes.find("0 (one path per work-item), 4, 8 or 16"), std::string::npos) << lanes;
    for (const char* bad : {"eight", "-8", "8.0", " 8", "32"}) EXPECT_NE(refusal({{"ORB_SIMD_LANES", bad}}), "") << bad;

    const std::string pass = refusal({{"ORB_PASS_SPP", "0"}});
    EXPECT_NE(pass.find("ORB_PASS_SPP='0'"), std::string::npos) << pass;
    EXPECT_NE(pass.find("a whole number of samples from 1 to 4096"), std::string::npos) << pass;
    for (const char* bad : {"4097", "-1", "two", "1.5"}) EXPECT_NE(refusal({{"ORB_PASS_SPP", bad}}), "") << bad;

    const std::string limit = refusal({{"ORB_REFIT_COST_LIMIT", "2x"}});
    EXPECT_NE(limit.find("ORB_REFIT_COST_LIMIT='2x'"), std::string::npos) << limit;
    for (const char* bad : {"-1", "nan", "inf", "abc"}) EXPECT_NE(refusal({{"ORB_REFIT_COST_LIMIT", bad}}), "") << bad;

    const std::string log = refusal({{"ORB_SHOW_BUILD_LOG", "yes"}});
    EXPECT_NE(log.find("ORB_SHOW_BUILD_LOG='yes'"), std::string::npos) << log;
    EXPECT_NE(log.find("1 (on) or 0 (off)"), std::string::npos) << log;
}

TEST(DevelopmentKnobsParser, TheMovedCaptureKnobsAreNamedInAWarning)
{
    std::vector<std::string> warnings;
    parse({{"ORB_CAPTURE_PASS", "/tmp/capture"}, {"ORB_CAPTURE_SKIP", "8"}}, &warnings);
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_NE(warnings[0].find("ORB_CAPTURE_PASS is set but ignored"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("dev/README.md"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[1].find("ORB_CAPTURE_SKIP"), std::string::npos) << warnings[1];
}
