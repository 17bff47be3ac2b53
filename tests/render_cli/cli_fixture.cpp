#include "cli_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "orb/scene/scene_json.h"

namespace fs = std::filesystem;

namespace orb::test {

std::string render_exe() { return ORB_RENDER_EXE; }

Scene small_scene() {
    Scene scene;
    scene.camera.position = {0.0, 1.0, 6.0};
    scene.camera.target = {0.0, 0.6, 0.0};
    scene.camera.up = {0.0, 1.0, 0.0};
    scene.camera.vfov_deg = 45.0;
    scene.render.width = 32;
    scene.render.height = 24;
    scene.render.spp = 4;
    scene.render.max_depth = 6;

    Material white{"white", MaterialType::Diffuse, {0.75, 0.75, 0.75}, {0, 0, 0}, 1.5};
    Material red{"red", MaterialType::Diffuse, {0.8, 0.2, 0.2}, {0, 0, 0}, 1.5};
    Material mirror{"mirror", MaterialType::Mirror, {0.95, 0.95, 0.95}, {0, 0, 0}, 1.5};
    Material light{"light", MaterialType::Diffuse, {0, 0, 0}, {12.0, 11.0, 9.0}, 1.5};
    scene.materials = {white, red, mirror, light};
    scene.spheres = {
        Sphere{"floor", {0.0, -1000.0, 0.0}, 1000.0, 0},
        Sphere{"ball", {-0.8, 0.7, 0.0}, 0.7, 1},
        Sphere{"mirror ball", {0.9, 0.5, 0.5}, 0.5, 2},
        Sphere{"lamp", {0.3, 2.6, -0.5}, 0.45, 3},
    };
    return scene;
}

Scene moving_ball_scene() {
    Scene scene = small_scene();
    AnimationNode node;
    node.name = "mover";
    AnimationChannel channel;
    channel.path = AnimationPath::Translation;
    channel.interpolation = Interpolation::Linear;
    channel.times = {0.0, 1.0};
    channel.values = {{-1.5, 0.7, 0.0, 0.0}, {1.5, 0.7, 0.0, 0.0}};
    node.channels.push_back(channel);
    scene.animation.nodes.push_back(node);
    scene.animation.spheres.push_back(SphereBinding{1, 0, {0.0, 0.0, 0.0}, 0.7});
    return scene;
}

void RenderCli::SetUp() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = (fs::temp_directory_path() / ("orb-render-cli-" + std::to_string(::getpid())) /
            (std::string(info->test_suite_name()) + "." + info->name()))
               .string();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
}

std::string RenderCli::path(const std::string& name) const { return (fs::path(dir_) / name).string(); }

std::string RenderCli::write_scene(const Scene& scene, const std::string& name) const {
    const std::string file = path(name);
    std::ofstream(file) << write_scene_json(scene);
    return file;
}

ProcessResult RenderCli::render(const std::vector<std::string>& args, const std::string& stdin_path,
                                const std::string& stdout_path) const {
    std::vector<std::string> argv{render_exe()};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_process(argv, stdin_path, stdout_path);
}

ProcessResult RenderCli::merge(const std::vector<std::string>& args) const {
    std::vector<std::string> argv{ORB_MERGE_EXE};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_process(argv);
}

std::vector<std::string> RenderCli::files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

bool has_exact_sums(const exr::testing::RawExr& image) { return image.attribute_types.count("orb:exactSums") > 0; }

void expect_same_image(const exr::testing::RawExr& a, const exr::testing::RawExr& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    const auto is_exact_sum = [](const std::string& name) { return name.rfind("orb.sum.", 0) == 0; };
    const bool both_exact = has_exact_sums(a) && has_exact_sums(b);
    for (const exr::testing::RawExr* image : {&a, &b}) {
        const exr::testing::RawExr& other = image == &a ? b : a;
        for (const auto& [name, values] : image->channels) {
            if (!other.channels.count(name)) {
                EXPECT_TRUE(is_exact_sum(name) && !both_exact) << "channel " << name << " is in one image only";
            }
        }
    }
    for (const auto& [name, values] : a.channels) {
        const auto found = b.channels.find(name);
        if (found == b.channels.end()) continue;
        if (is_exact_sum(name)) {
            EXPECT_EQ(a.uints.at(name), b.uints.at(name)) << "exact sums " << name;
            continue;
        }
        std::size_t differing = 0, first = 0;
        for (std::size_t i = 0; i < values.size(); ++i) {
            const bool same = std::memcmp(&values[i], &found->second[i], sizeof(float)) == 0;
            if (!same && differing++ == 0) first = i;
        }
        EXPECT_EQ(differing, 0u) << "channel " << name << ": " << differing << " of " << values.size()
                                 << " pixels differ, the first (" << first % static_cast<std::size_t>(a.width) << ", "
                                 << first / static_cast<std::size_t>(a.width) << "): " << values[first] << " vs "
                                 << found->second[first];
    }
}

void expect_same_within_float_rounding(const exr::testing::RawExr& a, const exr::testing::RawExr& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    constexpr double kRelative = 1e-5;  // ~80 float ulps
    for (const auto& [name, values] : a.channels) {
        if (name.rfind("orb.sum.", 0) == 0) continue;
        const auto found = b.channels.find(name);
        ASSERT_NE(found, b.channels.end()) << name;
        const auto& other = found->second;
        int reported = 0;
        for (std::size_t i = 0; i < values.size(); ++i) {
            const double x = values[i], y = other[i];
            if (std::isinf(x) || std::isinf(y)) {
                EXPECT_EQ(x, y) << name << "[" << i << "]";
                continue;
            }
            double tolerance = kRelative * std::max(std::fabs(x), std::fabs(y));
            if (name.rfind("N.", 0) == 0) tolerance = 1e-4;  // renormalised unit vectors
            if (name.rfind("variance.", 0) == 0) {
                // var = (sum_sq/n - mean^2)/(n-1) cancels; its rounding scales with mean^2/(n-1).
                const std::string c = name.substr(9);
                const double mean = a.channels.at(c)[i];
                tolerance += kRelative * mean * mean;
            }
            if (std::fabs(x - y) > tolerance && reported++ < 5)
                ADD_FAILURE() << name << "[" << i << "]: " << x << " vs " << y;
        }
    }
}

void expect_same_image(const std::string& path_a, const std::string& path_b) {
    expect_same_image(exr::testing::read_raw_exr(path_a), exr::testing::read_raw_exr(path_b));
}

}  // namespace orb::test
