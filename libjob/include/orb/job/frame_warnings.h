// What a run of frames (--frame/--frames) would render in vain, said before
// anything is rendered: a scene without animation gives the same image at
// every frame, and past the end of its animation a scene holds its last pose.
#pragma once

#include <string>
#include <vector>

#include "orb/scene/scene.h"

namespace orb::job {

// The warnings for rendering `frames` of `scene` at `fps`, each naming
// `label` (the scene's file); none when every frame shows something new.
// `camera_moves`: the command line moves the camera from frame to frame (a
// turntable), so the frames of a static scene differ and that warning is
// not given; frames past the animation's end are still named.
std::vector<std::string> frame_warnings(const Scene& scene, const std::vector<long>& frames, double fps,
                                        bool camera_moves, const std::string& label);

}  // namespace orb::job
