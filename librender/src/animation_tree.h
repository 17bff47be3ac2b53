// The sphere BVH of each frame of an animation: the previous frame's tree
// refitted to the moved spheres while that costs less than building anew,
// a new build when not (docs/rendering.md, "Frames: refit or rebuild").
#pragma once

#include <cstddef>
#include <optional>

#include "orb/scene/scene.h"
#include "sphere_bvh.h"

namespace orb::render {

// Never a refitted tree whose SAH cost (bvh_sah_cost) passes this multiple
// of the cost the tree was built with, however short the frames: past it
// the tree is a poor one for any ray count. The development knob
// ORB_REFIT_COST_LIMIT replaces it and the time rule below: refit up to
// that growth whatever the frames cost (0: never refit).
inline constexpr double kRefitCostLimit = 2.0;

class AnimationTree {
public:
    // `refit_cost_limit` (DevelopmentKnobs::refit_cost_limit): the limit
    // that replaces kRefitCostLimit and the time rule; none: both apply.
    explicit AnimationTree(std::optional<double> refit_cost_limit = std::nullopt)
        : refit_cost_limit_(refit_cost_limit)
    {
    }

    // The tree for `scene` (use_bvh false: none). When the scene has as many
    // spheres as the last, the last tree is refitted, and kept when the time
    // its larger cost is expected to add to a frame -- the cost's growth
    // (cost / cost built - 1, which bounded the measured slowdown of
    // traversal) times the previous frame's render seconds -- is less than
    // the time a new build would take beyond the refit (the last build's
    // seconds, less the refit's). Else, or past kRefitCostLimit, a new build
    // (scene_bvh, which also checks the spheres).
    const SphereBvh& tree_for(const Scene& scene, bool use_bvh, double last_frame_render_seconds);

    bool last_refitted() const { return last_refitted_; }  // the last tree_for refitted
    double last_seconds() const { return last_seconds_; }   // what the last tree_for took (refit, build or both)
    std::size_t node_count() const { return tree_.nodes.size(); }  // of the last tree (0: none)

private:
    const SphereBvh& choose(const Scene& scene, bool use_bvh, double last_frame_render_seconds);
    const SphereBvh& rebuild(const Scene& scene, bool use_bvh);

    std::optional<double> refit_cost_limit_;
    SphereBvh tree_;
    bool has_tree_ = false;
    bool use_bvh_ = true;
    std::size_t sphere_count_ = 0;
    double built_cost_ = 0;     // bvh_sah_cost of tree_ when it was built
    double build_seconds_ = 0;  // how long that build took
    bool last_refitted_ = false;
    double last_seconds_ = 0;
};

}  // namespace orb::render
