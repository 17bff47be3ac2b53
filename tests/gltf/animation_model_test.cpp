// The animation model on its own: channel evaluation per the glTF spec and
// the checks on the "animation" section of the scene JSON.
#include <gtest/gtest.h>

#include <cmath>

#include "orb/scene/animation.h"
#include "orb/scene/error.h"
#include "orb/scene/scene.h"
#include "orb/scene/scene_json.h"

namespace orb {
namespace {

AnimationChannel channel(AnimationPath path, Interpolation mode, std::vector<double> times,
                         std::vector<std::array<double, 4>> values) {
    AnimationChannel c;
    c.path = path;
    c.interpolation = mode;
    c.times = std::move(times);
    c.values = std::move(values);
    return c;
}

TEST(AnimationModel, LinearStepAndClamping) {
    const auto lin = channel(AnimationPath::Translation, Interpolation::Linear, {1, 3}, {{0, 0, 0, 0}, {4, -2, 8, 0}});
    EXPECT_EQ(evaluate_channel(lin, 2.0), (std::array<double, 4>{2, -1, 4, 0}));
    EXPECT_EQ(evaluate_channel(lin, 0.0), (std::array<double, 4>{0, 0, 0, 0}));
    EXPECT_EQ(evaluate_channel(lin, 9.0), (std::array<double, 4>{4, -2, 8, 0}));
    auto step = lin;
    step.interpolation = Interpolation::Step;
    EXPECT_EQ(evaluate_channel(step, 2.9)[0], 0.0);
    EXPECT_EQ(evaluate_channel(step, 3.0)[0], 4.0);
    const auto single = channel(AnimationPath::Scale, Interpolation::Linear, {0.5}, {{2, 2, 2, 0}});
    EXPECT_EQ(evaluate_channel(single, 0.0)[0], 2.0);
    EXPECT_EQ(evaluate_channel(single, 7.0)[0], 2.0);
}

TEST(AnimationModel, SlerpTakesTheShorterArcAndStaysUnit) {
    const double h = std::sqrt(0.5);
    // 0 -> 90 degrees about z, but the end is given as the negated quaternion.
    const auto rot = channel(AnimationPath::Rotation, Interpolation::Linear, {0, 1}, {{0, 0, 0, 1}, {0, 0, -h, -h}});
    const auto q = evaluate_channel(rot, 0.5);
    const double angle = 2 * std::atan2(std::fabs(q[2]), std::fabs(q[3]));
    EXPECT_NEAR(angle, M_PI / 4, 1e-12);
    EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-12);
    // Constant angular speed: a third of the way is 30 degrees.
    const auto third = evaluate_channel(rot, 1.0 / 3.0);
    EXPECT_NEAR(2 * std::atan2(std::fabs(third[2]), std::fabs(third[3])), M_PI / 6, 1e-12);
}

TEST(AnimationModel, CubicSplineHermiteWithIntervalScaledTangents) {
    // One component, keys at t=1 (value 1, out-tangent 2) and t=3 (in-tangent -1, value 5).
    const auto c = channel(AnimationPath::Translation, Interpolation::CubicSpline, {1, 3},
                           {{9, 0, 0, 0}, {1, 0, 0, 0}, {2, 0, 0, 0}, {-1, 0, 0, 0}, {5, 0, 0, 0}, {9, 0, 0, 0}});
    for (double t : {1.0, 1.5, 2.0, 2.7, 3.0}) {
        const double s = (t - 1) / 2, s2 = s * s, s3 = s2 * s;
        const double want = (2 * s3 - 3 * s2 + 1) * 1 + (s3 - 2 * s2 + s) * 2 * 2 + (-2 * s3 + 3 * s2) * 5 +
                            (s3 - s2) * 2 * -1;
        EXPECT_NEAR(evaluate_channel(c, t)[0], want, 1e-12) << t;
    }
    EXPECT_EQ(evaluate_channel(c, 0.0)[0], 1.0);  // clamped to the value, never a tangent
    EXPECT_EQ(evaluate_channel(c, 4.0)[0], 5.0);
}

Scene animated_scene() {
    Scene scene;
    scene.materials.push_back(Material{});
    scene.spheres.push_back(Sphere{});
    AnimationNode root;
    root.name = "root";
    root.channels.push_back(
        channel(AnimationPath::Translation, Interpolation::Linear, {0, 1}, {{0, 0, 0, 0}, {10, 0, 0, 0}}));
    AnimationNode child;
    child.parent = 0;
    child.translation = {0, 1, 0};
    child.scale = {2, 2, 2};
    scene.animation.nodes = {root, child};
    scene.animation.spheres.push_back(SphereBinding{0, 1, {0, 0, 1}, 0.5});
    return scene;
}

TEST(AnimationModel, BindingsFollowTheHierarchy) {
    const Scene at = scene_at_time(animated_scene(), 0.25);
    EXPECT_EQ(at.spheres[0].center, (Vec3{2.5, 1, 2}));
    EXPECT_EQ(at.spheres[0].radius, 1.0);
}

TEST(AnimationModel, JsonChecksNameThePath) {
    const std::string good = write_scene_json(animated_scene());
    EXPECT_EQ(load_scene_json(good, "a.json"), animated_scene());
    struct Case {
        std::string from, to, path;
    };
    const Case cases[] = {
        {"\"parent\": 0", "\"parent\": 1", "animation.nodes[1].parent"},
        {"\"times\": [0, 1]", "\"times\": [1, 0]", "animation.nodes[0].channels[0].times[1]"},
        {"\"times\": [0, 1]", "\"times\": [0, 1, 2]", "animation.nodes[0].channels[0].values"},
        {"\"interpolation\": \"LINEAR\"", "\"interpolation\": \"CUBIC\"", "animation.nodes[0].channels[0].interpolation"},
        {"\"sphere\": 0", "\"sphere\": 3", "animation.spheres[0].sphere"},
        {"\"node\": 1", "\"node\": 7", "animation.spheres[0].node"},
    };
    for (const Case& c : cases) {
        std::string text = good;
        const auto at = text.find(c.from);
        ASSERT_NE(at, std::string::npos) << c.from << " not in\n" << good;
        text.replace(at, c.from.size(), c.to);
        try {
            load_scene_json(text, "a.json");
            ADD_FAILURE() << "accepted " << c.to;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("a.json: " + c.path), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace orb
