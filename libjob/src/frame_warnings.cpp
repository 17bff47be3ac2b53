#include "orb/job/frame_warnings.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "orb/job/request_settings.h"

namespace orb::job {
namespace {

std::string number(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

}  // namespace

std::vector<std::string> frame_warnings(const Scene& scene, const std::vector<long>& frames, double fps,
                                        bool camera_moves, const std::string& label) {
    std::vector<std::string> warnings;
    if (scene.animation.empty()) {
        if (frames.size() > 1 && !camera_moves)
            warnings.push_back(label + ": the scene has no animation: all " + std::to_string(frames.size()) +
                               " frames are the same image");
        return warnings;
    }
    const double end = scene.animation.end_time();
    // Frame times are frame / fps, rounded: a frame that lands on the last keyframe is not past it.
    const double slack = 1e-9 * std::max(1.0, std::abs(end));
    std::vector<long> held;
    for (long frame : frames)
        if (frame_time(frame, fps) > end + slack) held.push_back(frame);
    if (held.empty()) return warnings;
    const double end_frame = end * fps;
    const long last_moving = static_cast<long>(std::floor(end_frame + 1e-9));
    const std::string where = std::abs(end_frame - std::round(end_frame)) < 1e-9
                                  ? "at frame " + std::to_string(last_moving)
                                  : "after frame " + std::to_string(last_moving);
    const std::string which = held.size() == 1 ? "frame " + std::to_string(held.front()) + " holds"
                                               : "the " + std::to_string(held.size()) + " frames from " +
                                                     std::to_string(held.front()) + " to " +
                                                     std::to_string(held.back()) + " hold";
    warnings.push_back(label + ": the animation ends at " + number(end) + " s, " + where + " (" + number(fps) +
                       " fps): " + which + " its last pose");
    return warnings;
}

}  // namespace orb::job
