// The automatic camera every importer shares (orb/scene/auto_framing.h):
// stray spheres are left out, and the framed spheres fill the image's
// tighter direction, but for the margin, at any aspect ratio.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "orb/scene/auto_framing.h"

namespace orb {
namespace {

// A fixed sequence in [0, 1) (xorshift64*), the same on every platform.
class Uniform {
public:
    double operator()() {
        state_ ^= state_ >> 12;
        state_ ^= state_ << 25;
        state_ ^= state_ >> 27;
        return static_cast<double>((state_ * 0x2545F4914F6CDD1DULL) >> 11) * 0x1.0p-53;
    }

private:
    std::uint64_t state_ = 88172645463325252ULL;
};

// `count` spheres of radius 0.01 spread evenly over the box `lo` ... `hi`.
std::vector<Sphere> cloud(std::size_t count, const Vec3& lo, const Vec3& hi) {
    Uniform u;
    std::vector<Sphere> spheres(count);
    for (Sphere& s : spheres) {
        for (int c = 0; c < 3; ++c) s.center[c] = lo[c] + (hi[c] - lo[c]) * u();
        s.radius = 0.01;
    }
    return spheres;
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 unit(const Vec3& v) {
    const double l = std::sqrt(dot(v, v));
    return {v[0] / l, v[1] / l, v[2] / l};
}

// How far the spheres reach across the image seen from the framing, as a
// fraction of the half-width and of the half-height: the largest
// tan(angle of the centre + angular radius) over tan(half field of view).
struct Reach {
    double across = 0, upward = 0;
};
Reach reach(const std::vector<Sphere>& spheres, const Framing& f, const FramingView& view) {
    const Vec3 forward = unit(sub(f.target, f.position));
    const Vec3 right = unit(cross(forward, view.up));
    const Vec3 up = cross(right, forward);
    const double tan_v = std::tan(view.vfov_deg * std::numbers::pi / 360);
    const double tan_h = tan_v * view.width / view.height;
    Reach r;
    for (const Sphere& s : spheres) {
        const Vec3 p = sub(s.center, f.position);
        const double depth = dot(p, forward), x = std::fabs(dot(p, right)), y = std::fabs(dot(p, up));
        EXPECT_GT(depth, s.radius);
        r.across = std::max(r.across, std::tan(std::atan2(x, depth) + std::asin(s.radius / std::hypot(x, depth))) / tan_h);
        r.upward = std::max(r.upward, std::tan(std::atan2(y, depth) + std::asin(s.radius / std::hypot(y, depth))) / tan_v);
    }
    return r;
}

constexpr double kFill = 1.0 / (1.0 + kFramingMargin);

// The spheres a framing counts: those wholly inside its box, which for
// spheres of one radius are exactly they.
std::vector<Sphere> framed_by(const std::vector<Sphere>& spheres, const Framing& f) {
    std::vector<Sphere> framed;
    for (const Sphere& s : spheres) {
        bool inside = true;
        for (int c = 0; c < 3; ++c) inside = inside && s.center[c] - s.radius >= f.lo[c] && s.center[c] + s.radius <= f.hi[c];
        if (inside) framed.push_back(s);
    }
    EXPECT_EQ(framed.size(), f.framed);
    return framed;
}

TEST(AutoFraming, FarOutliersDoNotShrinkTheCloud) {
    std::vector<Sphere> spheres = cloud(2000, {-1, -0.5, -0.7}, {1, 0.5, 0.7});
    const FramingView view;
    const Framing alone = *frame_spheres(spheres, view);
    for (const Vec3& far : {Vec3{100, 0, 0}, Vec3{-60, 80, 3}, Vec3{0, -1e4, 0}, Vec3{5, 5, 500}, Vec3{-3, 0, -90}})
        spheres.push_back(Sphere{"stray", far, 0.01, 0});
    const Framing with_strays = *frame_spheres(spheres, view);
    // 2005 spheres: the strays lie far outside the cloud's core box (its
    // centres without the 20 lowest and highest per axis), the whole cloud
    // within a tenth of the core's size of it: exactly the cloud is framed.
    EXPECT_EQ(alone.framed, 2000u);
    EXPECT_EQ(with_strays.framed, 2000u);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(with_strays.target[c], alone.target[c]) << c;
    EXPECT_EQ(with_strays.distance, alone.distance);
    const Reach cloud_reach = reach(std::vector<Sphere>(spheres.begin(), spheres.begin() + 2000), with_strays, view);
    EXPECT_NEAR(std::max(cloud_reach.across, cloud_reach.upward), kFill, 1e-9) << "the cloud fills the image";
    // Strays just beyond the cloud (within a tenth of its size) are part of it.
    spheres.push_back(Sphere{"near", {1.15, 0, 0}, 0.01, 0});
    EXPECT_EQ(frame_spheres(spheres, view)->framed, 2001u);
}

TEST(AutoFraming, TheFramedSpheresFillTheTighterDirectionAtEveryAspectRatio) {
    const std::vector<Sphere> wide = cloud(3000, {-2, -0.5, -0.5}, {2, 0.5, 0.5});
    const std::vector<Sphere> tall = cloud(3000, {-0.3, -1.5, -0.3}, {0.3, 1.5, 0.3});
    for (const auto* spheres : {&wide, &tall}) {
        for (const auto& [width, height] : {std::pair{1920, 600}, {640, 480}, {500, 500}, {300, 900}, {64, 640}}) {
            FramingView view;
            view.width = width;
            view.height = height;
            const Framing f = *frame_spheres(*spheres, view);
            const Reach r = reach(framed_by(*spheres, f), f, view);
            const std::string label = (spheres == &wide ? "wide " : "tall ") + std::to_string(width) + "x" +
                                      std::to_string(height);
            EXPECT_NEAR(std::max(r.across, r.upward), kFill, 1e-9) << label;
            EXPECT_LE(std::min(r.across, r.upward), kFill + 1e-9) << label;
        }
    }
    // A wide image of a wide scene is filled across, a tall one of a tall scene up and down.
    FramingView banner;
    banner.width = 1920;
    banner.height = 600;
    const Framing wide_banner = *frame_spheres(wide, banner);
    const Reach across = reach(framed_by(wide, wide_banner), wide_banner, banner);
    EXPECT_NEAR(across.across, kFill, 1e-9);
    EXPECT_LT(across.upward, 0.9 * kFill);
    FramingView portrait;
    portrait.width = 300;
    portrait.height = 900;
    const Framing tall_portrait = *frame_spheres(tall, portrait);
    const Reach upward = reach(framed_by(tall, tall_portrait), tall_portrait, portrait);
    EXPECT_NEAR(upward.upward, kFill, 1e-9);
    EXPECT_LT(upward.across, 0.9 * kFill);
}

TEST(AutoFraming, UnderAHundredSpheresEveryOneIsFramed) {
    std::vector<Sphere> spheres = cloud(98, {-1, -1, -1}, {1, 1, 1});
    spheres.push_back(Sphere{"far", {40, 0, 0}, 1, 0});
    const FramingView view;
    const Framing f = *frame_spheres(spheres, view);
    EXPECT_EQ(f.framed, 99u);
    EXPECT_DOUBLE_EQ(f.hi[0], 41);
    const Reach r = reach(spheres, f, view);
    EXPECT_NEAR(std::max(r.across, r.upward), kFill, 1e-9);
}

TEST(AutoFraming, SkippedSpheresDoNotCountAndTheViewIsHonoured) {
    std::vector<Sphere> spheres = cloud(50, {-1, -1, -1}, {1, 1, 1});
    spheres.push_back(Sphere{"sun", {0, 1e6, 0}, 1e4, 0});
    FramingView view;
    view.toward_camera = {0, 1, 1};  // from 45 degrees up
    const auto f = frame_spheres(spheres, view, [&](std::size_t i) { return i == spheres.size() - 1; });
    ASSERT_TRUE(f);
    EXPECT_EQ(f->framed, 50u);
    const Vec3 back = unit(sub(f->position, f->target));
    EXPECT_NEAR(back[0], 0, 1e-12);
    EXPECT_NEAR(back[1], std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(back[2], std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(std::sqrt(dot(sub(f->position, f->target), sub(f->position, f->target))), f->distance, 1e-12);
    const Reach r = reach(std::vector<Sphere>(spheres.begin(), spheres.end() - 1), *f, view);
    EXPECT_NEAR(std::max(r.across, r.upward), kFill, 1e-9);
    EXPECT_FALSE(frame_spheres(spheres, view, [](std::size_t) { return true; }));
    EXPECT_FALSE(frame_spheres({}, view));
}

}  // namespace
}  // namespace orb
