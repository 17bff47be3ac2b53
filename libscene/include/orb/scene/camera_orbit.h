// A turntable: the camera turned about its look-at point (docs/orb-render.md,
// "Camera").
#pragma once

#include "orb/scene/scene.h"

namespace orb {

// The camera turned by `degrees` about the axis through its target along its
// up vector, right-handed (a positive turn is counter-clockwise seen from
// the side `up` points to). Target, up, lens and field of view stay; the
// view keeps its elevation. Whole quarter turns are exact (90 degrees takes
// (0, 0, 5) about +y to exactly (5, 0, 0)). `up` must not be the zero vector.
Camera orbit_camera(const Camera& camera, double degrees);

// The turn at `frame` of an orbit of `degrees` over the frames first ... last:
// degrees * (frame - first) / (last - first + 1). The frame after the last
// would be at `degrees`, so a 360-degree orbit loops without repeating a
// frame; a frame outside the range continues the same rate.
double orbit_angle_deg(double degrees, long frame, long first, long last);

}  // namespace orb
