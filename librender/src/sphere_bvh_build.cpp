// Binned SAH construction of the sphere BVH (sphere_bvh.h). Each node tries
// `bins` planes per axis over its centroids' extent and keeps the cheapest by
// the surface area heuristic; near the root, a node whose two sides both hold
// many spheres builds them on two threads, and a node that splits off a few
// spheres hands its spare threads on to the larger side. The tree is built as
// linked nodes per thread and flattened at the end into depth-first order
// with adjacent children.
// A split the SAH picks is kept only while the tree stays within
// kBvhMaxDepth levels; past that budget nodes split at the median.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <thread>

#include "sphere_bvh.h"

namespace orb::render {
namespace {

float round_down(double v) {
    float f = static_cast<float>(v);
    if (static_cast<double>(f) > v) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}

float round_up(double v) {
    float f = static_cast<float>(v);
    if (static_cast<double>(f) < v) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

// 32 bytes, so that partitioning a million of them moves little memory. The
// box is already rounded outward to float, as the device will store it.
struct Prim {
    std::array<float, 3> lo, hi;
    std::array<float, 1> pad_;  // unused; keeps the index 4-byte aligned after 24 bytes of floats
    std::uint32_t index;
    float centre(int axis) const { return 0.5f * (lo[axis] + hi[axis]); }
};
static_assert(sizeof(Prim) == 32);

// A bin's bounds, in the prims' own float precision.
struct FloatBox {
    std::array<float, 3> lo{std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::infinity()};
    std::array<float, 3> hi{-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity()};
    void grow(const Prim& p) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], p.lo[a]);
            hi[a] = std::max(hi[a], p.hi[a]);
        }
    }
    void grow(const FloatBox& b) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], b.lo[a]);
            hi[a] = std::max(hi[a], b.hi[a]);
        }
    }
    void grow_point(const Prim& p) {
        for (int a = 0; a < 3; ++a) {
            const float c = p.centre(a);
            lo[a] = std::min(lo[a], c);
            hi[a] = std::max(hi[a], c);
        }
    }
    double extent(int axis) const { return double(hi[axis]) - lo[axis]; }
    double area() const {
        if (lo[0] > hi[0]) return 0.0;
        const double x = double(hi[0]) - lo[0], y = double(hi[1]) - lo[1], z = double(hi[2]) - lo[2];
        return 2.0 * (x * y + y * z + z * x);
    }
};

// A sphere's box (and the scene's) before rounding to float.
struct Box {
    std::array<double, 3> lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity()};
    std::array<double, 3> hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()};

    void grow(const Box& b) {
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], b.lo[a]);
            hi[a] = std::max(hi[a], b.hi[a]);
        }
    }
    bool empty() const { return lo[0] > hi[0]; }
    double area() const {
        if (empty()) return 0.0;
        const double x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
        return 2.0 * (x * y + y * z + z * x);
    }
};


// The sphere's box, widened so that it also holds the sphere as the device
// stores it (float centre, float radius squared: each off by a float ulp or
// so of the largest coordinate involved).
Box sphere_box(const Sphere& s) {
    const double largest = std::max({std::abs(s.center[0]), std::abs(s.center[1]), std::abs(s.center[2])}) + s.radius;
    const double pad = largest * 0x1p-20;
    Box b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = s.center[a] - s.radius - pad;
        b.hi[a] = s.center[a] + s.radius + pad;
    }
    return b;
}

// Levels (leaves included) of the tree that median splits build over n
// prims: each split leaves at most ceil(n / 2) on either side.
int median_levels(std::uint64_t n) {
    int levels = 1;
    for (; n > static_cast<std::uint64_t>(kBvhMaxLeafSize); n = (n + 1) / 2) ++levels;
    return levels;
}

// The depth guarantee: a node at depth d (the root has 1) over n prims
// satisfies d - 1 + median_levels(n) <= kBvhMaxDepth. The root does for any
// count of prims a uint32 can index (median_levels(2^32) = 31), a median
// split keeps it for both children, and an SAH split is taken only when it
// keeps it too. So no leaf is deeper than kBvhMaxDepth, however the SAH
// would have split (a chain of ever smaller clusters, say).
static_assert(31 <= kBvhMaxDepth, "the root of any tree satisfies the depth guarantee");
constexpr std::uint32_t kParallelMinimum = 4096;  // smaller subtrees are not worth a thread
constexpr int kMaxBins = 64;

struct Builder;

struct BuildNode {
    FloatBox box;  // the prims' boxes are float already, so their union is exact
    std::uint32_t begin = 0, end = 0;  // range in the shared prim array (leaves)
    std::int32_t left = -1, right = -1;  // children in the same builder, or
    const Builder* left_builder = nullptr;  // a left subtree built on another thread
    bool leaf() const { return left < 0 && !left_builder; }
};

struct Builder {
    std::vector<Prim>& prims;
    const BvhSettings& settings;
    std::vector<BuildNode> nodes;
    std::vector<std::unique_ptr<Builder>> children;  // builders of subtrees run on other threads
    const std::uint32_t started_over;                 // the prims of the subtree this builder builds

    Builder(std::vector<Prim>& p, const BvhSettings& s, std::uint32_t count)
        : prims(p), settings(s), started_over(count) {}

    // The most prims one builder (one thread) built, less those it handed on.
    std::uint32_t most_prims_on_one_thread() const {
        std::uint32_t own = started_over, most = 0;
        for (const auto& child : children) {
            own -= child->started_over;
            most = std::max(most, child->most_prims_on_one_thread());
        }
        return std::max(own, most);
    }

    // Builds prims[begin, end) and returns its root's index in `nodes`.
    std::int32_t build(std::uint32_t begin, std::uint32_t end, int depth, unsigned spare_threads) {
        const auto index = static_cast<std::int32_t>(nodes.size());
        nodes.emplace_back();
        FloatBox centroids;
        for (std::uint32_t i = begin; i < end; ++i) {
            nodes[index].box.grow(prims[i]);
            centroids.grow_point(prims[i]);
        }
        nodes[index].begin = begin;
        nodes[index].end = end;
        // A leaf of up to four spheres is one packet test (one vector
        // instruction per float4 on CPUs), as cheap as a leaf of one: small
        // nodes always stop, without searching for a split.
        if (end - begin <= kBvhMaxLeafSize) return index;

        std::uint32_t middle = split(begin, end, centroids, depth);
        if (middle == begin || middle == end) middle = median_split(begin, end, centroids);
        const std::uint32_t smaller = std::min(middle - begin, end - middle);
        if (spare_threads > 0 && smaller >= kParallelMinimum && 8 * std::uint64_t{smaller} >= end - begin) {
            auto other = std::make_unique<Builder>(prims, settings, middle - begin);
            const unsigned left_share = spare_threads / 2, right_share = spare_threads - 1 - left_share;
            std::thread worker([&] { other->build(begin, middle, depth + 1, left_share); });
            const std::int32_t right = build(middle, end, depth + 1, right_share);
            worker.join();
            nodes[index].left_builder = other.get();
            nodes[index].right = right;
            children.push_back(std::move(other));
        } else {
            // A side too small for a thread of its own (or a small share of
            // the node) is built here, and the spare threads go on with the
            // other: an SAH split that cuts off a few large spheres near the
            // root must not leave the millions below it to one thread.
            const bool left_larger = middle - begin >= end - middle;
            const std::int32_t left = build(begin, middle, depth + 1, left_larger ? spare_threads : 0);
            const std::int32_t right = build(middle, end, depth + 1, left_larger ? 0 : spare_threads);
            nodes[index].left = left;
            nodes[index].right = right;
        }
        return index;
    }

    // The SAH split of prims[begin, end) of a node at `depth`: the index
    // where the right part starts, or begin when no plane separates the
    // centroids or the split would break the depth guarantee (the caller
    // then splits at the median).
    std::uint32_t split(std::uint32_t begin, std::uint32_t end, const FloatBox& centroids, int depth) {
        const int bins = std::clamp(settings.bins, 2, kMaxBins);
        double best_cost = std::numeric_limits<double>::infinity();
        int best_axis = -1, best_plane = 0;
        // One pass bins every prim on all three axes (one read of each prim).
        std::array<std::array<FloatBox, kMaxBins>, 3> bin_box{};
        std::array<std::array<std::uint32_t, kMaxBins>, 3> bin_count{};
        std::array<float, 3> lo{}, scale{};
        for (int axis = 0; axis < 3; ++axis) {
            const double extent = centroids.extent(axis);
            lo[axis] = centroids.lo[axis];
            scale[axis] = extent > 0.0 ? static_cast<float>(bins / extent) : 0.0f;
        }
        for (std::uint32_t i = begin; i < end; ++i) {
            const Prim& p = prims[i];
            for (int axis = 0; axis < 3; ++axis) {
                const int b = bin_of(p.centre(axis), lo[axis], scale[axis], bins);
                bin_box[axis][b].grow(p);
                ++bin_count[axis][b];
            }
        }
        std::array<double, kMaxBins> right_area;
        std::array<std::uint32_t, kMaxBins> right_count;
        for (int axis = 0; axis < 3; ++axis) {
            if (scale[axis] == 0.0f) continue;
            FloatBox right;
            std::uint32_t count = 0;
            for (int b = bins - 1; b > 0; --b) {
                right.grow(bin_box[axis][b]);
                count += bin_count[axis][b];
                right_area[b] = right.area();
                right_count[b] = count;
            }
            FloatBox left;
            count = 0;
            for (int plane = 1; plane < bins; ++plane) {  // left: bins [0, plane)
                left.grow(bin_box[axis][plane - 1]);
                count += bin_count[axis][plane - 1];
                if (count == 0 || right_count[plane] == 0) continue;
                const double cost = left.area() * count + right_area[plane] * right_count[plane];
                if (cost < best_cost) {
                    best_cost = cost;
                    best_axis = axis;
                    best_plane = plane;
                }
            }
        }
        if (best_axis < 0) return begin;
        std::uint32_t left_count = 0;
        for (int b = 0; b < best_plane; ++b) left_count += bin_count[best_axis][b];
        const std::uint32_t larger = std::max(left_count, (end - begin) - left_count);
        if (depth + median_levels(larger) > kBvhMaxDepth) return begin;  // the depth guarantee above
        const auto middle = std::partition(prims.begin() + begin, prims.begin() + end, [&](const Prim& p) {
            return bin_of(p.centre(best_axis), lo[best_axis], scale[best_axis], bins) < best_plane;
        });
        return static_cast<std::uint32_t>(middle - prims.begin());
    }

    // The same float arithmetic when binning and partitioning, so every prim
    // lands on the side its bin was counted on.
    static int bin_of(float c, float lo, float scale, int bins) {
        return std::clamp(static_cast<int>((c - lo) * scale), 0, bins - 1);
    }

    std::uint32_t median_split(std::uint32_t begin, std::uint32_t end, const FloatBox& centroids) {
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (centroids.extent(a) > centroids.extent(axis)) axis = a;
        const std::uint32_t middle = begin + (end - begin) / 2;
        std::nth_element(prims.begin() + begin, prims.begin() + middle, prims.begin() + end,
                         [axis](const Prim& a, const Prim& b) { return a.centre(axis) < b.centre(axis); });
        return middle;
    }
};

struct Flattener {
    const std::vector<Prim>& prims;
    BinaryBvh& out;

    void emit(const Builder& builder, std::int32_t index, std::size_t slot) {
        const BuildNode& node = builder.nodes[index];
        BinaryBvhNode& flat = out.nodes[slot];
        for (int a = 0; a < 3; ++a) {
            flat.lo[a] = node.box.lo[a];
            flat.hi[a] = node.box.hi[a];
        }
        if (node.leaf()) {
            flat.first = static_cast<std::uint32_t>(out.order.size());
            flat.count = node.end - node.begin;
            for (std::uint32_t i = node.begin; i < node.end; ++i) out.order.push_back(prims[i].index);
            return;
        }
        const std::size_t children = out.nodes.size();
        out.nodes[slot].first = static_cast<std::uint32_t>(children);
        out.nodes[slot].count = 0;
        out.nodes.resize(children + 2);  // `flat` may dangle from here on
        if (node.left_builder)
            emit(*node.left_builder, 0, children);
        else
            emit(builder, node.left, children);
        emit(builder, node.right, children + 1);
    }
};

// Spheres whose box takes `huge_area_fraction` of the whole scene's box area
// (the largest first, at most `max_outside` of them), or every sphere of a
// small scene.
std::vector<std::uint32_t> choose_outside(std::span<const Sphere> spheres, const BvhSettings& settings) {
    std::vector<std::uint32_t> outside;
    if (spheres.size() < settings.min_spheres_for_tree) {
        for (std::uint32_t i = 0; i < spheres.size(); ++i) outside.push_back(i);
        return outside;
    }
    Box scene;
    for (const Sphere& s : spheres) scene.grow(sphere_box(s));
    const double limit = settings.huge_area_fraction * scene.area();
    for (std::uint32_t i = 0; i < spheres.size(); ++i)
        if (sphere_box(spheres[i]).area() >= limit) outside.push_back(i);
    if (outside.size() > settings.max_outside) {
        std::nth_element(outside.begin(), outside.begin() + static_cast<std::ptrdiff_t>(settings.max_outside),
                         outside.end(),
                         [&](std::uint32_t a, std::uint32_t b) { return spheres[a].radius > spheres[b].radius; });
        outside.resize(settings.max_outside);
    }
    std::sort(outside.begin(), outside.end());
    return outside;
}

}  // namespace

void sphere_float_box(const Sphere& sphere, float lo[3], float hi[3])
{
    const Box box = sphere_box(sphere);
    for (int a = 0; a < 3; ++a) {
        lo[a] = round_down(box.lo[a]);
        hi[a] = round_up(box.hi[a]);
    }
}

BinaryBvh build_binary_bvh(std::span<const Sphere> spheres, const BvhSettings& settings) {
    BinaryBvh bvh;
    bvh.outside = choose_outside(spheres, settings);

    std::vector<char> is_outside(spheres.size(), 0);
    for (std::uint32_t i : bvh.outside) is_outside[i] = 1;
    std::vector<Prim> prims;
    prims.reserve(spheres.size() - bvh.outside.size());
    for (std::uint32_t i = 0; i < spheres.size(); ++i) {
        if (is_outside[i]) continue;
        Prim p{};
        sphere_float_box(spheres[i], p.lo.data(), p.hi.data());
        p.index = i;
        prims.push_back(p);
    }
    if (prims.empty()) return bvh;

    const unsigned threads = settings.threads ? settings.threads : std::max(1u, std::thread::hardware_concurrency());
    Builder root(prims, settings, static_cast<std::uint32_t>(prims.size()));
    root.build(0, static_cast<std::uint32_t>(prims.size()), 1, threads - 1);

    bvh.nodes.reserve(2 * prims.size());
    bvh.order.reserve(prims.size());
    bvh.nodes.resize(1);
    Flattener{prims, bvh}.emit(root, 0, 0);
    bvh.most_spheres_on_one_thread = root.most_prims_on_one_thread();
    return bvh;
}

}  // namespace orb::render
