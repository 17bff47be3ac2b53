// Evaluates an Animation at a moment, exactly as glTF 2.0 defines keyframe
// interpolation (section 3.11 "Animations" and appendix C of the spec).
#include "orb/scene/animation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "orb/scene/detail/animation_math.h"
#include "orb/scene/scene.h"

namespace orb {
namespace {

using Value = std::array<double, 4>;

bool is_rotation(const AnimationChannel& channel) { return channel.path == AnimationPath::Rotation; }

// CUBICSPLINE stores (in-tangent, value, out-tangent) per key.
Value key_value(const AnimationChannel& channel, std::size_t key) {
    return channel.interpolation == Interpolation::CubicSpline ? channel.values[key * 3 + 1] : channel.values[key];
}

Value lerp(const Value& a, const Value& b, double s) {
    return {a[0] + (b[0] - a[0]) * s, a[1] + (b[1] - a[1]) * s, a[2] + (b[2] - a[2]) * s, a[3] + (b[3] - a[3]) * s};
}

// Hermite spline between keys k and k+1; the tangents are per second, so
// they are scaled by the interval length (glTF appendix C).
Value cubic(const AnimationChannel& channel, std::size_t k, double s, double interval) {
    const Value& v0 = channel.values[k * 3 + 1];
    const Value& out0 = channel.values[k * 3 + 2];
    const Value& in1 = channel.values[(k + 1) * 3 + 0];
    const Value& v1 = channel.values[(k + 1) * 3 + 1];
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    Value result{};
    for (int c = 0; c < 4; ++c)
        result[c] = h00 * v0[c] + h10 * interval * out0[c] + h01 * v1[c] + h11 * interval * in1[c];
    return result;
}

}  // namespace

Value evaluate_channel(const AnimationChannel& channel, double seconds) {
    const std::vector<double>& times = channel.times;
    if (times.empty()) return {0, 0, 0, 0};
    Value result;
    if (!(seconds > times.front())) {
        result = key_value(channel, 0);  // before the first key (or NaN): hold the first value
    } else if (seconds >= times.back()) {
        result = key_value(channel, times.size() - 1);
    } else {
        // times[k] <= seconds < times[k + 1]
        const std::size_t k = std::size_t(std::upper_bound(times.begin(), times.end(), seconds) - times.begin()) - 1;
        const double interval = times[k + 1] - times[k];
        const double s = (seconds - times[k]) / interval;
        switch (channel.interpolation) {
            case Interpolation::Step: result = key_value(channel, k); break;
            case Interpolation::Linear:
                if (is_rotation(channel)) {
                    const Value a = key_value(channel, k), b = key_value(channel, k + 1);
                    result = detail::slerp(detail::normalized(a), detail::normalized(b), s);
                } else {
                    result = lerp(key_value(channel, k), key_value(channel, k + 1), s);
                }
                break;
            case Interpolation::CubicSpline: result = cubic(channel, k, s, interval); break;
        }
    }
    if (is_rotation(channel)) result = detail::normalized(result);
    return result;
}

double Animation::start_time() const {
    double start = std::numeric_limits<double>::infinity();
    for (const AnimationNode& node : nodes)
        for (const AnimationChannel& channel : node.channels)
            if (!channel.times.empty()) start = std::min(start, channel.times.front());
    return std::isfinite(start) ? start : 0.0;
}

double Animation::end_time() const {
    double end = -std::numeric_limits<double>::infinity();
    for (const AnimationNode& node : nodes)
        for (const AnimationChannel& channel : node.channels)
            if (!channel.times.empty()) end = std::max(end, channel.times.back());
    return std::isfinite(end) ? end : 0.0;
}

namespace {

Matrix4 local_matrix(const AnimationNode& node, double seconds) {
    if (node.has_matrix) return node.matrix;
    AnimVec3 t = node.translation, s = node.scale;
    Quaternion r = node.rotation;
    for (const AnimationChannel& channel : node.channels) {
        const Value v = evaluate_channel(channel, seconds);
        switch (channel.path) {
            case AnimationPath::Translation: t = {v[0], v[1], v[2]}; break;
            case AnimationPath::Rotation: r = v; break;
            case AnimationPath::Scale: s = {v[0], v[1], v[2]}; break;
        }
    }
    return detail::trs_matrix(t, r, s);
}

// Parents always come before their children, so one forward pass suffices.
std::vector<Matrix4> world_matrices(const Animation& animation, double seconds) {
    std::vector<Matrix4> world(animation.nodes.size());
    for (std::size_t i = 0; i < animation.nodes.size(); ++i) {
        const AnimationNode& node = animation.nodes[i];
        const Matrix4 local = local_matrix(node, seconds);
        const bool has_parent = node.parent >= 0 && std::size_t(node.parent) < i;
        world[i] = has_parent ? detail::multiply(world[std::size_t(node.parent)], local) : local;
    }
    return world;
}

}  // namespace

Matrix4 node_world_matrix(const Animation& animation, std::size_t node, double seconds) {
    Matrix4 world = kIdentityMatrix;
    // Walk up the chain; parents have smaller indices, so this terminates.
    for (std::size_t i = node; i < animation.nodes.size();) {
        world = detail::multiply(local_matrix(animation.nodes[i], seconds), world);
        const std::int32_t parent = animation.nodes[i].parent;
        if (parent < 0 || std::size_t(parent) >= i) break;
        i = std::size_t(parent);
    }
    return world;
}

Scene scene_at_time(const Scene& scene, double seconds) {
    Scene result = scene;
    const Animation& animation = scene.animation;
    if (animation.empty()) return result;
    const std::vector<Matrix4> world = world_matrices(animation, seconds);

    for (const SphereBinding& binding : animation.spheres) {
        if (binding.sphere >= result.spheres.size() || binding.node >= world.size()) continue;
        const Matrix4& m = world[binding.node];
        Sphere& sphere = result.spheres[binding.sphere];
        sphere.center = detail::transform_point(m, binding.center);
        sphere.radius = binding.radius * detail::largest_axis_scale(m);
    }

    if (animation.camera_node >= 0 && std::size_t(animation.camera_node) < world.size()) {
        const Matrix4& m = world[std::size_t(animation.camera_node)];
        Camera& camera = result.camera;
        const Vec3 rest_view{camera.target[0] - camera.position[0], camera.target[1] - camera.position[1],
                             camera.target[2] - camera.position[2]};
        const double target_distance = detail::length3(rest_view) > 0 ? detail::length3(rest_view) : 1.0;
        AnimVec3 forward = detail::transform_direction(m, {0, 0, -1});
        AnimVec3 up = detail::transform_direction(m, {0, 1, 0});
        const double forward_length = detail::length3(forward);
        // A degenerate (zero-scale) camera node keeps the rest camera.
        if (forward_length > 0 && detail::length3(up) > 0) {
            for (double& c : forward) c /= forward_length;
            // Remove any shear so that up is perpendicular to the view.
            const double along = detail::dot3(up, forward);
            for (int c = 0; c < 3; ++c) up[c] -= along * forward[c];
            const double up_length = detail::length3(up);
            if (up_length > 0) {
                const AnimVec3 position = detail::transform_point(m, {0, 0, 0});
                camera.position = position;
                for (int c = 0; c < 3; ++c) {
                    camera.target[c] = position[c] + forward[c] * target_distance;
                    camera.up[c] = up[c] / up_length;
                }
            }
        }
    }
    result.animation = Animation{};
    return result;
}

}  // namespace orb
