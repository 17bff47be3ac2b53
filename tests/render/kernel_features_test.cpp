// The kernel features' table (libtables/include/orb/tables/kernel_features.h):
// the host's defaults are what a program of the kernels reads, the options
// carry every feature the host changes and nothing twice, and every change
// reaches the binary cache's key.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "device_renderer.h"
#include "opencl_devices.h"
#include "orb/kernels/embedded.h"
#include "orb/tables/kernel_features.h"
#include "orb/render/device.h"
#include "program_build.h"
#include "program_source.h"
#include "render_test_support.h"
#include "scene_layout.h"

namespace orb::render::test {
namespace {

using device::KernelFeatures;

constexpr std::size_t kTextBytes = 32;  // per row: a token's spelling, NUL-terminated

// Appended to a program: for every row of the table, the value the program
// sees (a number's bits) and, for every row, its spelling after expansion.
constexpr const char* kReportKernel = R"(
#define ORB_REPORT_TEXT2(x) #x
#define ORB_REPORT_TEXT(x) ORB_REPORT_TEXT2(x)
#define ORB_REPORT_Bool(NAME) (uint)(NAME)
#define ORB_REPORT_Int(NAME) (uint)(int)(NAME)
#define ORB_REPORT_Uint(NAME) (uint)(NAME)
#define ORB_REPORT_Float(NAME) as_uint((float)(NAME))
#define ORB_REPORT_Token(NAME) 0u
inline void report_text(__global char* out, __constant const char* text)
{
    int i = 0;
    for (; i < 31 && text[i] != 0; ++i) out[i] = text[i];
    out[i] = 0;
}
#define ORB_REPORT_ROW(NAME, member, Type, value, meaning)             \
    values[row] = ORB_REPORT_##Type(NAME);                             \
    report_text(text + row * 32, ORB_REPORT_TEXT(NAME));               \
    ++row;
__kernel void report_features(__global uint* values, __global char* text)
{
    int row = 0;
    ORB_KERNEL_FEATURES(ORB_REPORT_ROW)
}
)";

struct Report {
    std::vector<std::uint32_t> values;
    std::vector<std::string> texts;
};

// Builds `source` + the report kernel with `options` on the test device and
// runs it once.
Report report(const std::string& source, const std::string& options)
{
    const DeviceInfo info = choose_device("");
    const cl::Device device = opencl_device(info.index);
    const cl::Context context(device);
    cl::CommandQueue queue(context, device);
    cl::Program program(context, source + kReportKernel);
    try {
        program.build({device}, options.c_str());
    } catch (const cl::Error&) {
        throw std::runtime_error("the report kernel failed to build: " + program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device));
    }
    const std::size_t rows = device::kKernelFeatures.size();
    cl::Buffer values(context, CL_MEM_WRITE_ONLY, rows * sizeof(cl_uint));
    cl::Buffer text(context, CL_MEM_WRITE_ONLY, rows * kTextBytes);
    cl::Kernel kernel(program, "report_features");
    kernel.setArg(0, values);
    kernel.setArg(1, text);
    queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(1), cl::NDRange(1));
    Report out;
    out.values.resize(rows);
    std::vector<char> chars(rows * kTextBytes);
    queue.enqueueReadBuffer(values, CL_TRUE, 0, rows * sizeof(cl_uint), out.values.data());
    queue.enqueueReadBuffer(text, CL_TRUE, 0, chars.size(), chars.data());
    for (std::size_t row = 0; row < rows; ++row) out.texts.emplace_back(chars.data() + row * kTextBytes);
    return out;
}

// What the report kernel should read for a host value.
std::uint32_t expected_bits(bool value) { return value ? 1u : 0u; }
std::uint32_t expected_bits(int value) { return static_cast<std::uint32_t>(value); }
std::uint32_t expected_bits(std::uint32_t value) { return value; }
std::uint32_t expected_bits(float value) { return std::bit_cast<std::uint32_t>(value); }
std::uint32_t expected_bits(const std::string&) { return 0u; }

// Every row of the program's report holds `features`' value.
void expect_report_holds(const Report& got, const KernelFeatures& features)
{
    std::size_t row = 0;
    device::for_each_kernel_feature(features, features, [&](const device::KernelFeatureInfo& info, const auto& value,
                                                            const auto&) {
        EXPECT_EQ(got.values[row], expected_bits(value)) << info.name << " as the kernels read it: " << got.texts[row];
        if constexpr (std::is_same_v<std::decay_t<decltype(value)>, std::string>) {
            EXPECT_EQ(got.texts[row], value) << info.name;
        }
        ++row;
    });
}

// A value of each type other than `value`, and one the kernels accept
// (ORB_LANES 1 becomes 4).
bool changed(bool value) { return !value; }
int changed(int value) { return value + 3; }
std::uint32_t changed(std::uint32_t value) { return value ^ 0x5u; }
float changed(float value) { return value + 0.5f; }
std::string changed(const std::string& value) { return value == "__global" ? "__constant" : "__global"; }

// Every feature changed.
KernelFeatures all_changed()
{
    KernelFeatures features;
#define ORB_TEST_CHANGE(NAME, member, Type, value, meaning) features.member = changed(features.member);
    ORB_KERNEL_FEATURES(ORB_TEST_CHANGE)
#undef ORB_TEST_CHANGE
    return features;
}

// One variant per row, with only that row's feature changed.
struct OneChange {
    std::string name;
    KernelFeatures features;
};
std::vector<OneChange> one_change_each()
{
    std::vector<OneChange> variants;
#define ORB_TEST_CHANGE_ONE(NAME, member, Type, value, meaning) \
    {                                                           \
        KernelFeatures features;                                \
        features.member = changed(features.member);             \
        variants.push_back({#NAME, features});                  \
    }
    ORB_KERNEL_FEATURES(ORB_TEST_CHANGE_ONE)
#undef ORB_TEST_CHANGE_ONE
    return variants;
}

// The -D names of an option string, in order.
std::vector<std::string> defined_names(const std::string& options)
{
    std::vector<std::string> names;
    std::istringstream words(options);
    std::string word;
    while (words >> word)
        if (word.rfind("-D", 0) == 0) names.push_back(word.substr(2, word.find('=') - 2));
    return names;
}

}  // namespace

TEST(KernelFeatures, TheTableNamesEachSymbolAndMemberOnce)
{
    std::set<std::string> names, members;
    for (const device::KernelFeatureInfo& info : device::kKernelFeatures) {
        EXPECT_TRUE(names.insert(info.name).second) << info.name;
        EXPECT_TRUE(members.insert(info.member).second) << info.member;
        EXPECT_GT(std::string(info.meaning).size(), 10u) << info.name << " needs its meaning";
    }
}

// The whole program, built without a feature option: every kernel file sees
// the table's defaults (a file that defined a feature its own way would
// show here).
TEST(KernelFeatures, TheKernelsReadTheHostDefaults)
{
    expect_report_holds(report(program_source(""), kKernelLanguageOptions), KernelFeatures{});
}

// Every feature changed through the options reaches the kernels, with the
// value the host holds (floats to the bit, unsigned values whole).
TEST(KernelFeatures, EveryChangedFeatureReachesTheKernels)
{
    const KernelFeatures features = all_changed();
    const std::string source = device::kernel_feature_defaults() +
                               std::string(kernels::find_embedded_kernel("include/orb/tables/kernel_features.h"));
    expect_report_holds(report(source, "-cl-std=CL1.2 " + device::kernel_feature_options(features)), features);
    // Floats a text form could get wrong: no fraction, tiny, many digits.
    KernelFeatures floats;
    for (float value : {0.0f, 1.0f, 1e-7f, 0.1f, 3.4e38f}) {
        floats.caster_share = value;
        floats.rr_threshold = -value;
        expect_report_holds(report(source, "-cl-std=CL1.2 " + device::kernel_feature_options(floats)), floats);
    }
}

TEST(KernelFeatures, TheOptionsCarryTheChangedFeaturesOnceInTableOrder)
{
    EXPECT_EQ(device::kernel_feature_options(KernelFeatures{}), "");
    const std::vector<std::string> names = defined_names(device::kernel_feature_options(all_changed()));
    ASSERT_EQ(names.size(), device::kKernelFeatures.size());
    for (std::size_t row = 0; row < names.size(); ++row) EXPECT_EQ(names[row], device::kKernelFeatures[row].name);
    for (const OneChange& variant : one_change_each())
        EXPECT_EQ(defined_names(device::kernel_feature_options(variant.features)), std::vector<std::string>{variant.name});
    // Against a base: only what differs from it.
    KernelFeatures base;
    base.bvh = false;
    KernelFeatures target = base;
    target.lanes = 8;
    EXPECT_EQ(device::kernel_feature_options(target, base), "-DORB_LANES=8");
}

// The options render_pass is really built with on this device, for scenes
// that set different features: no symbol twice.
TEST(KernelFeatures, TheRenderersOptionsDefineNothingTwice)
{
    std::vector<Scene> scenes{load_scene_file(std::string(ORB_SCENES_DIR) + "/cornell.scn"), every_branch_scene()};
    Scene lit = every_branch_scene();
    lit.environment.kind = EnvironmentKind::Color;
    lit.environment.color = {0.2, 0.3, 0.4};
    scenes.push_back(lit);
    const std::shared_ptr<DeviceSession> session = DeviceSession::open(choose_device(""), {});
    for (const Scene& scene : scenes)
        for (int lanes : {0, 8}) {
            const std::string options =
                render_program_options(*session, layout_scene(scene), small_config(8, 8), lanes);
            const std::vector<std::string> names = defined_names(options);
            EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size()) << options;
            EXPECT_EQ(options.rfind(kKernelLanguageOptions, 0), 0u) << options;
        }
}

// The binary cache's key changes with every feature, each to a key of its own.
TEST(KernelFeatures, EveryFeatureChangesTheCacheKey)
{
    const cl::Device device = opencl_device(choose_device("").index);
    const std::string source = program_source("");
    const std::string base_key = program_cache_key(device, source, program_options_text(ProgramOptions{}));
    EXPECT_EQ(program_cache_key(device, source, program_options_text(ProgramOptions{})), base_key);  // deterministic
    std::set<std::string> keys{base_key};
    for (const OneChange& variant : one_change_each())
        EXPECT_TRUE(keys.insert(program_cache_key(device, source, program_options_text({variant.features}))).second)
            << variant.name;
    ProgramOptions capped;
    capped.nvidia_max_registers = 64;
    EXPECT_TRUE(keys.insert(program_cache_key(device, source, program_options_text(capped))).second);
}

TEST(KernelFeatures, ValuesTheKernelsCannotReadAreRefused)
{
    KernelFeatures features;
    for (const char* token : {"", "__global x", "a=b"}) {
        features.scene_space = token;
        EXPECT_THROW(device::kernel_feature_options(features), std::invalid_argument) << token;
    }
    features = KernelFeatures{};
    features.caster_share = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(device::kernel_feature_options(features), std::invalid_argument);
    features.caster_share = std::numeric_limits<float>::infinity();
    EXPECT_THROW(device::kernel_feature_options(features), std::invalid_argument);
}

}  // namespace orb::render::test
