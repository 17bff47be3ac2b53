#include "cli_fixture.h"

#include <algorithm>
#include <cmath>
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

void expect_same_within_float_rounding(const exr::testing::RawExr& a, const exr::testing::RawExr& b) {
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    ASSERT_EQ(a.channels.size(), b.channels.size());
    constexpr double kRelative = 1e-5;  // ~80 float ulps
    for (const auto& [name, values] : a.channels) {
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

void expect_sums_within(const exr::ExrFilm& a, const exr::ExrFilm& b, double relative_bound) {
    const double n = static_cast<double>(a.film.samples_per_pixel);
    for (const orb::film::ChannelInfo& info : orb::film::kChannels) {
        const auto& x = a.film.channel(info.channel);
        const auto& y = b.film.channel(info.channel);
        ASSERT_EQ(x.size(), y.size()) << info.name;
        if (info.merge == orb::film::MergeRule::Same) {
            EXPECT_EQ(x, y) << info.name;  // the pixel-centre ray: no sum at all
            continue;
        }
        int reported = 0;
        for (std::size_t i = 0; i < x.size(); ++i) {
            const double magnitude = info.stored_as == orb::film::StoredAs::UnitVector
                                         ? n
                                         : std::max(std::fabs(double(x[i])), std::fabs(double(y[i])));
            if (std::fabs(double(x[i]) - y[i]) > relative_bound * magnitude && reported++ < 5)
                ADD_FAILURE() << info.name << "[" << i << "]: " << x[i] << " vs " << y[i] << " (bound "
                              << relative_bound * magnitude << ")";
        }
    }
}

}  // namespace orb::test
