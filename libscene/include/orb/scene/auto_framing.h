// The automatic camera: where an importer puts the camera of a scene that
// brings none (a glTF asset without cameras, a PLY point cloud). One rule
// for every importer, documented in docs/orb-import.md ("Automatic camera").
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "orb/scene/scene.h"

namespace orb {

// A few stray points must not shrink a scan to a dot. Per axis, the sphere
// centres' bounds are taken without the floor(n / 100) lowest and the
// floor(n / 100) highest (about the 1st and 99th percentiles; under 100
// spheres, all of them): the core box. A sphere whose centre lies outside
// the core box grown on every side by a tenth of its largest side is a
// stray and is not framed; every other sphere is, the tails of the cloud
// included, so the framing cuts off nothing of the cloud itself.
inline constexpr std::size_t kFramingOutlierDivisor = 100;
inline constexpr double kFramingStrayReach = 0.1;

// The framed spheres fill 1 / (1 + margin) of the image's half-width or
// half-height, whichever binds first: 10% of room around them.
inline constexpr double kFramingMargin = 0.1;

// Which points are strays by the rule above: those outside [lo, hi].
struct StrayBounds {
    Vec3 lo{}, hi{};
    bool keeps(const Vec3& point) const;
};
StrayBounds stray_bounds(const std::vector<Vec3>& points);  // points not empty

struct FramingView {
    Vec3 toward_camera{0.0, 0.0, 1.0};  // from the framed centre towards the camera; any length > 0
    Vec3 up{0.0, 1.0, 0.0};             // not parallel to toward_camera
    double vfov_deg = Camera{}.vfov_deg;
    int width = RenderSettings{}.width;
    int height = RenderSettings{}.height;
};

struct Framing {
    Vec3 target{};      // the centre of the framed spheres' bounding box
    Vec3 position{};    // target + toward_camera * distance
    double distance = 0;
    Vec3 lo{}, hi{};    // the framed spheres' bounding box (centres +- radii)
    std::size_t framed = 0;  // how many spheres are framed
};

// The camera position that shows the framed spheres (see above), looking
// along -toward_camera at the centre of their box, as close as it can be
// while every framed sphere lies wholly inside the view with the margin:
// the sphere nearest an edge touches the margin there, so the box fills the
// image in whichever direction (across or up) is tighter for this aspect
// ratio. Spheres for which `skip` is true are not counted at all. None when
// no sphere counts.
std::optional<Framing> frame_spheres(const std::vector<Sphere>& spheres, const FramingView& view,
                                     const std::function<bool(std::size_t)>& skip = {});

}  // namespace orb
