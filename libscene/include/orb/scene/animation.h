// Animation of a canonical scene (docs/scene-format.md, "animation").
//
// The static scene holds every object at its rest pose. An Animation is a
// small node hierarchy in the spirit of glTF: each node has a rest transform
// (a fixed matrix, or translation/rotation/scale) and optional keyframe
// channels that override its translation, rotation or scale over time.
// Spheres and the camera are bound to nodes; scene_at_time() evaluates the
// channels exactly as the glTF 2.0 specification defines them and places the
// bound objects. An empty animation (no nodes) is a static scene.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace orb {

struct Scene;

using AnimVec3 = std::array<double, 3>;
using Quaternion = std::array<double, 4>;  // x, y, z, w (glTF order); unit length
using Matrix4 = std::array<double, 16>;    // column-major (glTF order)

inline constexpr Matrix4 kIdentityMatrix{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

enum class AnimationPath { Translation, Rotation, Scale };
enum class Interpolation { Linear, Step, CubicSpline };

struct AnimationChannel {
    AnimationPath path = AnimationPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<double> times;  // seconds, finite, strictly increasing, at least one
    // LINEAR/STEP: one value per time. CUBICSPLINE: three per time, in the
    // order in-tangent, value, out-tangent (as glTF stores them). Translation
    // and scale use components 0..2 (the fourth is 0); rotation uses all four.
    std::vector<std::array<double, 4>> values;
    bool operator==(const AnimationChannel&) const = default;
};

struct AnimationNode {
    std::string name;
    std::int32_t parent = -1;  // index of an earlier node, or -1 for a root
    // Rest transform: a fixed matrix (never animated), or T * R * S.
    bool has_matrix = false;
    Matrix4 matrix = kIdentityMatrix;
    AnimVec3 translation{0.0, 0.0, 0.0};
    Quaternion rotation{0.0, 0.0, 0.0, 1.0};
    AnimVec3 scale{1.0, 1.0, 1.0};
    std::vector<AnimationChannel> channels;  // at most one per path; none when has_matrix
    bool operator==(const AnimationNode&) const = default;
};

// A sphere that moves with a node: its world centre is the node's world
// matrix applied to `center`; its world radius is `radius` times the largest
// axis scale of that matrix.
struct SphereBinding {
    std::uint32_t sphere = 0;  // index into Scene::spheres
    std::uint32_t node = 0;    // index into Animation::nodes
    AnimVec3 center{0.0, 0.0, 0.0};
    double radius = 1.0;
    bool operator==(const SphereBinding&) const = default;
};

struct Animation {
    std::vector<AnimationNode> nodes;
    std::vector<SphereBinding> spheres;
    // The camera sits at the node's origin, looks down its -z and has its +y
    // up (the glTF camera convention); -1: the camera does not move.
    std::int32_t camera_node = -1;

    bool empty() const { return nodes.empty(); }
    double start_time() const;  // earliest keyframe (0 when there is none)
    double end_time() const;    // latest keyframe (0 when there is none)
    bool operator==(const Animation&) const = default;
};

// Value of one channel at `seconds` (clamped to the first/last keyframe).
std::array<double, 4> evaluate_channel(const AnimationChannel& channel, double seconds);

// World matrix of node `node` at `seconds`.
Matrix4 node_world_matrix(const Animation& animation, std::size_t node, double seconds);

// The static scene at `seconds`: bound spheres and the camera placed, the
// animation section removed. A static scene is returned unchanged.
Scene scene_at_time(const Scene& scene, double seconds);

}  // namespace orb
