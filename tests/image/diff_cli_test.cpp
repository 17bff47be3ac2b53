// orb-diff end to end: metrics against idiff, gates and exit codes, reports.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <regex>

#include "orb/image/magma.h"
#include "test_support.h"

using namespace orb::image;
using namespace orb::image::test;
namespace fs = std::filesystem;

namespace {

const std::string kDiff = quote(diff_exe());

double idiff_value(const std::string& output, const std::string& label) {
    std::smatch m;
    if (!std::regex_search(output, m, std::regex(label + R"( *= *([0-9.eE+-]+))"))) {
        ADD_FAILURE() << "no '" << label << "' in: " << output;
        return NAN;
    }
    return std::stod(m[1]);
}

nlohmann::json report_of(const std::string& args, int expected_exit) {
    const auto r = run(kDiff + " " + args + " --json - -q");
    EXPECT_EQ(r.exit_code, expected_exit) << args << "\n" << r.err;
    try {
        return nlohmann::json::parse(r.out);
    } catch (const std::exception&) {
        ADD_FAILURE() << "no JSON report for " << args << ": " << r.out << r.err;
        return {};
    }
}

class DiffCli : public ::testing::Test {
protected:
    ScratchDir dir;
    std::string a = dir.path("a.exr"), b = dir.path("b.exr");
    void SetUp() override {
        write_exr(a, make_scene(64, 40, 5.0f));
        write_exr(b, make_scene(64, 40, 5.0f, 0.05f, 11));
    }
    std::string pair() const { return quote(a) + " " + quote(b); }
};

void expect_matches_idiff(const std::string& ref, const std::string& test) {
    const auto theirs = run("idiff " + quote(ref) + " " + quote(test));
    const auto report = report_of(quote(ref) + " " + quote(test), 1);
    const auto& m = report["passes"][0]["metrics"];
    auto close = [](double ours, double expected) { return std::fabs(ours - expected) <= 1e-5 * std::fabs(expected) + 1e-9; };
    EXPECT_PRED2(close, m["mean_abs_error"].get<double>(), idiff_value(theirs.out, "Mean error"));
    EXPECT_PRED2(close, m["rmse"].get<double>(), idiff_value(theirs.out, "RMS error"));
    EXPECT_NEAR(m["psnr"].get<double>(), idiff_value(theirs.out, "Peak SNR"), 1e-3);
    EXPECT_PRED2(close, m["max_abs_error"]["value"].get<double>(), idiff_value(theirs.out, "Max error"));
    std::smatch where;
    ASSERT_TRUE(std::regex_search(theirs.out, where, std::regex(R"(@ \((\d+), (\d+), (\w+)\))")));
    EXPECT_EQ(m["max_abs_error"]["x"].get<int>(), std::stoi(where[1]));
    EXPECT_EQ(m["max_abs_error"]["y"].get<int>(), std::stoi(where[2]));
    EXPECT_EQ(m["max_abs_error"]["channel"].get<std::string>(), where[3].str());
}

}  // namespace

TEST_F(DiffCli, MetricsMatchIdiffOnHdrAndLdrPairs) {
    expect_matches_idiff(a, b);
    write_png(dir.path("a.png"), make_scene(64, 40, 0.3f));
    write_png(dir.path("b.png"), make_scene(64, 40, 0.3f, 0.1f, 5));
    expect_matches_idiff(dir.path("a.png"), dir.path("b.png"));
    // oiiotool --diff reports the same numbers.
    const auto r = run("oiiotool " + pair() + " --diff");
    const auto report = report_of(pair(), 1);
    EXPECT_NEAR(report["passes"][0]["metrics"]["rmse"].get<double>(), idiff_value(r.out, "RMS error"), 1e-6);
}

TEST_F(DiffCli, RelMseAndPercentOverThreshold) {
    // Half of the pixels off by exactly 0.25 in red.
    Image ref(10, 10, {"R", "G", "B"}, 0.5f), test = ref;
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 10; ++x) test.at(x, y, 0) = 0.75f;
    write_exr(dir.path("r.exr"), ref);
    write_exr(dir.path("t.exr"), test);
    const std::string args = quote(dir.path("r.exr")) + " " + quote(dir.path("t.exr"));
    auto report = report_of(args + " --fail-percent 50 --fail-threshold 0.2", 0);
    const auto& m = report["passes"][0]["metrics"];
    EXPECT_DOUBLE_EQ(m["percent_over_fail_threshold"].get<double>(), 50.0);
    // relMSE: 50 of 300 values with 0.0625 / (0.25 + 0.01).
    EXPECT_NEAR(m["relmse"].get<double>(), 50.0 * 0.0625 / 0.26 / 300.0, 1e-9);
    report_of(args + " --fail-percent 49 --fail-threshold 0.2", 1);
    report_of(args + " --fail-percent 0 --fail-threshold 0.3", 0);
}

TEST_F(DiffCli, ExitCodesForPassWarnAndFail) {
    auto report = report_of(quote(a) + " " + quote(a), 0);
    EXPECT_EQ(report["verdict"], "pass");
    EXPECT_EQ(report["passes"][0]["metrics"]["psnr"], nullptr);  // infinite

    // Default gate: any difference beyond float rounding fails.
    EXPECT_EQ(report_of(pair(), 1)["verdict"], "fail");

    report = report_of(pair() + " --fail-rmse 1 --warn-rmse 1e-6", 0);
    EXPECT_EQ(report["verdict"], "warn");
    EXPECT_EQ(report["passes"][0]["warned"].size(), 1u);
    report_of(pair() + " --fail-rmse 1 --warn-rmse 1e-6 --strict", 1);
    report_of(pair() + " --fail-rmse 1 --fail-relmse 1 --fail-flip 1", 0);
    EXPECT_EQ(report_of(pair() + " --fail-flip 1e-4", 1)["passes"][0]["failed"][0].get<std::string>().rfind("flip", 0), 0u);
    report_of(pair() + " --fail-relmse 1e-9", 1);

    report = report_of(pair() + " --fail-rmse 0.5 --warn-flip 0.001 --warn-percent 10", 0);
    EXPECT_EQ(report["thresholds"]["fail"]["rmse"], 0.5);
    EXPECT_EQ(report["thresholds"]["warn"]["flip"], 0.001);
    EXPECT_EQ(report["thresholds"]["warn"]["percent"], 10.0);
    EXPECT_EQ(report["exit_code"], 0);
}

TEST_F(DiffCli, ErrorsExitWithTwo) {
    std::ifstream in(a, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir.path("trunc.exr"), std::ios::binary).write(bytes.data(), bytes.size() - 200);
    std::ofstream(dir.path("junk.png")) << "not a png";
    write_exr(dir.path("small.exr"), make_scene(32, 40, 5.0f));
    write_png(dir.path("a.png"), make_scene(64, 40, 0.3f));
    struct Case {
        std::string args, message;
    };
    const std::vector<Case> cases = {
        {quote(a) + " " + quote(dir.path("missing.exr")), "missing.exr: no such file"},
        {quote(a) + " " + quote(dir.path("trunc.exr")), "trunc.exr"},
        {quote(a) + " " + quote(dir.path("junk.png")), "junk.png"},
        {quote(a) + " " + quote(dir.path("small.exr")), "differ in size"},
        {pair() + " --pass direct", "no 'direct' pass"},
        {quote(a) + " " + quote(dir.path("a.png")), "--display"},
        {quote(a), "need two images"},
        {pair() + " --fail-rmse notanumber", "notanumber"},
    };
    for (const Case& c : cases) {
        const auto r = run(kDiff + " " + c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
    }
}

TEST_F(DiffCli, MeaninglessGateOrPpdValuesAreUsageErrors) {
    struct Case {
        std::string option, value, message;
    };
    const std::string non_negative = "expected a finite number >= 0, got '";
    const std::vector<Case> cases = {
        {"--fail-rmse", "nan", non_negative + "nan'"},
        {"--fail-relmse", "-1", non_negative + "-1'"},
        {"--fail-flip", "inf", non_negative + "inf'"},
        {"--fail-threshold", "-0.1", non_negative + "-0.1'"},
        {"--warn-threshold", "NaN", non_negative + "NaN'"},
        {"--warn-rmse", "-inf", non_negative + "-inf'"},
        {"--fail-percent", "150", "expected a percentage in [0, 100], got '150'"},
        {"--warn-percent", "nan", "expected a percentage in [0, 100], got 'nan'"},
        {"--ppd", "1e9", "expected pixels per degree in [1, 1000], got '1e9'"},
        {"--ppd", "0", "expected pixels per degree in [1, 1000], got '0'"},
        {"--ppd", "nan", "expected pixels per degree in [1, 1000], got 'nan'"},
    };
    const std::string outputs = " --json " + quote(dir.path("report.json")) + " --diff-image " + quote(dir.path("heat.png"));
    for (const Case& c : cases) {
        const auto r = run(kDiff + " " + pair() + " " + c.option + " " + c.value + outputs);
        EXPECT_EQ(r.exit_code, 2) << c.option << " " << c.value << "\n" << r.err;
        EXPECT_EQ(r.err.rfind("orb-diff: error: " + c.option + ": " + c.message + "\n", 0), 0u) << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
        EXPECT_FALSE(fs::exists(dir.path("report.json")));
        EXPECT_FALSE(fs::exists(dir.path("heat.png")));
    }
}

TEST_F(DiffCli, DefaultGateForgivesFloatRoundingButNotARealChange) {
    const Image reference = make_scene(64, 40, 5.0f);
    write_exr(dir.path("ref.exr"), reference);
    // Every value off by 3e-6 relative, as a resumed render's sums are.
    Image rounded = reference;
    for (float& v : rounded.pixels) v *= 1.0f + 3e-6f;
    write_exr(dir.path("rounded.exr"), rounded);
    const std::string rounding_pair = quote(dir.path("ref.exr")) + " " + quote(dir.path("rounded.exr"));
    auto report = report_of(rounding_pair, 0);
    EXPECT_EQ(report["verdict"], "pass");
    EXPECT_EQ(report["thresholds"]["fail"]["threshold"], 1e-6);
    EXPECT_EQ(report["thresholds"]["fail"]["relative_threshold"], 1e-4);
    const auto summary = run(kDiff + " " + rounding_pair);
    EXPECT_NE(summary.out.find(" 0% of pixels over 1e-06 + 0.0001*max(|a|,|b|), "), std::string::npos) << summary.out;
    EXPECT_NE(summary.out.find("verdict: pass"), std::string::npos) << summary.out;
    // An explicit threshold stays absolute: the same pair fails 1e-6.
    report = report_of(rounding_pair + " --fail-threshold 1e-6", 1);
    EXPECT_EQ(report["thresholds"]["fail"]["relative_threshold"], 0.0);

    // One channel of one pixel off by 1e-3 relative: a real change.
    Image changed = reference;
    changed.at(10, 10, 1) *= 1.001f;
    write_exr(dir.path("changed.exr"), changed);
    report = report_of(quote(dir.path("ref.exr")) + " " + quote(dir.path("changed.exr")), 1);
    EXPECT_EQ(report["verdict"], "fail");

    // Near zero the absolute floor decides: 5e-7 passes, 3e-6 fails.
    Image black(8, 8, {"R", "G", "B"}, 0.0f), speck = black, dust = black;
    speck.at(3, 3, 0) = 5e-7f;
    dust.at(3, 3, 0) = 3e-6f;
    write_exr(dir.path("black.exr"), black);
    write_exr(dir.path("speck.exr"), speck);
    write_exr(dir.path("dust.exr"), dust);
    report_of(quote(dir.path("black.exr")) + " " + quote(dir.path("speck.exr")), 0);
    report_of(quote(dir.path("black.exr")) + " " + quote(dir.path("dust.exr")), 1);
}

TEST_F(DiffCli, ReadsOneImageFromStdin) {
    const auto from_files = report_of(pair(), 1);
    const auto r = run("cat " + quote(b) + " | " + kDiff + " " + quote(a) + " - --json - -q");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    const auto from_stdin = nlohmann::json::parse(r.out);
    EXPECT_EQ(from_stdin["test"], "<stdin>");
    EXPECT_EQ(from_stdin["passes"][0]["metrics"], from_files["passes"][0]["metrics"]);
}

TEST_F(DiffCli, AllPassesReportEveryCommonPass) {
    write_exr(dir.path("m1.exr"), make_multipass(40, 24), true);
    Image changed = make_multipass(40, 24);
    changed.at(3, 4, changed.find_channel("Z")) += 1.0f;
    write_exr(dir.path("m2.exr"), changed, true);
    const auto report = report_of(quote(dir.path("m1.exr")) + " " + quote(dir.path("m2.exr")) + " --all-passes", 1);
    ASSERT_EQ(report["passes"].size(), 9u);
    for (const auto& p : report["passes"]) {
        const std::string name = p["pass"];
        const bool colour = p["kind"] == "color";
        EXPECT_EQ(p["metrics"]["flip"].is_object(), colour) << name;
        EXPECT_EQ(p["verdict"], name == "depth" ? "fail" : "pass") << name;
    }
    EXPECT_EQ(report["verdict"], "fail");
}

TEST_F(DiffCli, DiffImageUsesMagma) {
    auto r = run(kDiff + " " + quote(a) + " " + quote(a) + " --diff-image " + quote(dir.path("same.png")) + " -q");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Image same = read_image(dir.path("same.png"));
    ASSERT_EQ(same.width, 64);
    const auto black = magma(0.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(same.at(10, 10, c), black[c], 1.0 / 255);

    r = run(kDiff + " " + pair() + " --diff-image " + quote(dir.path("diff.png")) + " -q");
    EXPECT_EQ(r.exit_code, 1) << r.err;
    const Image diff = read_image(dir.path("diff.png"));
    double mean_same = 0, mean_diff = 0;
    for (size_t i = 0; i < same.pixels.size(); ++i) mean_same += same.pixels[i], mean_diff += diff.pixels[i];
    EXPECT_GT(mean_diff, mean_same);
}

TEST_F(DiffCli, ComparesThroughADisplayView) {
    const auto report = report_of(pair() + " --display sRGB --view Filmic", 1);
    const auto& p = report["passes"][0];
    EXPECT_EQ(p["space"], "display: sRGB / Filmic");
    EXPECT_EQ(p["metrics"]["flip"]["variant"], "LDR-FLIP");
    EXPECT_EQ(report["comparison"]["view"], "Filmic");
    // A display image against a render, compared as displayed.
    ASSERT_EQ(run(quote(tonemap_exe()) + " " + quote(a) + " --view Filmic -o " + quote(dir.path("a.png")) + " -q").exit_code, 0);
    const auto mixed = report_of(quote(dir.path("a.png")) + " " + quote(a) + " --view Filmic --fail-rmse 0.01", 0);
    EXPECT_LT(mixed["passes"][0]["metrics"]["max_abs_error"]["value"].get<double>(), 1.0 / 255 + 1e-6);
}
