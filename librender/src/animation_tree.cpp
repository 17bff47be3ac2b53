#include "animation_tree.h"

#include <chrono>

#include "scene_layout.h"

namespace orb::render {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

const SphereBvh& AnimationTree::tree_for(const Scene& scene, bool use_bvh, double last_frame_render_seconds)
{
    const auto began = std::chrono::steady_clock::now();
    const SphereBvh& tree = choose(scene, use_bvh, last_frame_render_seconds);
    last_seconds_ = seconds_since(began);
    return tree;
}

const SphereBvh& AnimationTree::choose(const Scene& scene, bool use_bvh, double last_frame_render_seconds)
{
    last_refitted_ = false;
    if (has_tree_ && use_bvh == use_bvh_ && scene.spheres.size() == sphere_count_ && !tree_.nodes.empty()) {
        const double limit = refit_cost_limit_.value_or(kRefitCostLimit);
        const bool weigh_time = !refit_cost_limit_;  // the development knob's limit alone
        const auto start = std::chrono::steady_clock::now();
        // In place: a refit reads only the tree's topology, and a refit that
        // is not kept is replaced by the rebuild below. A sphere the layout
        // will refuse (NaN, radius 0) makes the cost NaN or the boxes odd;
        // either way the rebuild's checks report it.
        refit_sphere_bvh(tree_, scene.spheres);
        const double refit_seconds = seconds_since(start);
        const double growth = bvh_sah_cost(tree_) / built_cost_;
        const double slower_frame = (growth - 1.0) * last_frame_render_seconds;
        const double build_saved = build_seconds_ - refit_seconds;
        if (growth <= limit && (!weigh_time || slower_frame <= build_saved)) {
            last_refitted_ = true;
            return tree_;
        }
    }
    return rebuild(scene, use_bvh);
}

const SphereBvh& AnimationTree::rebuild(const Scene& scene, bool use_bvh)
{
    const auto start = std::chrono::steady_clock::now();
    tree_ = scene_bvh(scene, use_bvh);
    build_seconds_ = seconds_since(start);
    has_tree_ = true;
    use_bvh_ = use_bvh;
    sphere_count_ = scene.spheres.size();
    built_cost_ = bvh_sah_cost(tree_);
    return tree_;
}

}  // namespace orb::render
